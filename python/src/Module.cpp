// SPDX-License-Identifier: Apache-2.0
// `import flarekit`: the library's jobs on numpy arrays and files (flarekit/__init__.py
// re-exports this extension, flarekit._flarekit).
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>

#include "Bindings.h"
#include "Convert.h"
#include "core/InstallPaths.h"
#include "flarekit/Limits.h"

#ifndef FLAREKIT_PY_TO_PRESETS
#define FLAREKIT_PY_TO_PRESETS "../../../../share/flarekit/presets"
#endif
#ifndef FLAREKIT_PY_TO_MODULES
#define FLAREKIT_PY_TO_MODULES "../../../flarekit"
#endif

namespace {

//! This extension's folder: an installed module finds its presets and image module from it
//! (relative paths computed by python/CMakeLists.txt), never from the building machine.
std::filesystem::path moduleFolder() {
    Dl_info info{};
    if (!dladdr(reinterpret_cast<void*>(&moduleFolder), &info) || !info.dli_fname) return {};
    return std::filesystem::path(info.dli_fname).parent_path();
}

}  // namespace

PYBIND11_MODULE(_flarekit, m) {
    namespace py = pybind11;
    using namespace flarekit;
    m.doc() = "flarekit: lens flares on numpy arrays and image files";
    if (const auto here = moduleFolder(); !here.empty())
        addShippedRoots(here / FLAREKIT_PY_TO_PRESETS, here / FLAREKIT_PY_TO_MODULES);
    // The CLI's environment variable sets the budget here too.
    if (const char* env = std::getenv("FLAREKIT_MAX_MEMORY"); env && *env) {
        if (const auto bytes = parseByteSize(env)) {
            ResourceLimits limits = resourceLimits();
            limits.maxMemoryBytes = *bytes;
            setResourceLimits(limits);
        }
    }
    m.def(
        "set_max_memory",
        [](std::uint64_t bytes) {
            ResourceLimits limits = resourceLimits();
            limits.maxMemoryBytes = bytes;
            setResourceLimits(limits);
        },
        py::arg("bytes"),
        "set_max_memory(bytes)\n\nThe memory budget every call is checked against before it "
        "allocates (default 4 GiB, or FLAREKIT_MAX_MEMORY as the CLI reads it).");
    m.def(
        "max_memory", [] { return resourceLimits().maxMemoryBytes; },
        "max_memory() -> int\n\nThe memory budget in bytes.");
    python::addJobs(m);
    python::addData(m);
    python::addImages(m);
    python::addSynth(m);
    python::addTemporal(m);
}
