// SPDX-License-Identifier: Apache-2.0
// Finds and opens libflarekit_oiio.so on first use (see OiioModule.h).
#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "core/InstallPaths.h"
#include "core/codecs/OiioModule.h"

namespace flarekit::codec {

namespace {

//! The places to look, in order: FLAREKIT_OIIO_MODULE, then beside this install or build
//! (core/InstallPaths.h), so a moved install still finds its own.
std::vector<std::string> candidates() {
    std::vector<std::string> out;
    if (const char* env = std::getenv("FLAREKIT_OIIO_MODULE"); env && *env) out.push_back(env);
    for (const auto& path : oiioModuleCandidates()) out.push_back(path.string());
    return out;
}

struct Loaded {
    const OiioModule* module = nullptr;
    std::string why;
};

Loaded load() {
    Loaded loaded;
    std::string tried;
    for (const std::string& path : candidates()) {
        if (path.empty() || access(path.c_str(), R_OK) != 0) continue;
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* e = dlerror();
            tried += (tried.empty() ? "" : "; ") + std::string(e ? e : path);
            continue;
        }
        using Entry = const OiioModule* (*)();
        auto entry = reinterpret_cast<Entry>(dlsym(handle, "flarekit_oiio_module"));
        const OiioModule* m = entry ? entry() : nullptr;
        if (m && m->abi == kOiioModuleAbi && m->rawSize == sizeof(Raw) &&
            m->samplesSize == sizeof(Samples)) {
            loaded.module = m;
            return loaded;
        }
        tried += (tried.empty() ? "" : "; ") + path + " is from another flarekit build";
        dlclose(handle);
    }
    loaded.why = tried.empty() ? "libflarekit_oiio.so not found (set FLAREKIT_OIIO_MODULE)" : tried;
    return loaded;
}

}  // namespace

const OiioModule* oiioModule(std::string* why) {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = load(); });
    if (!loaded.module && why) *why = loaded.why;
    return loaded.module;
}

}  // namespace flarekit::codec
