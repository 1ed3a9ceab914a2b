// SPDX-License-Identifier: Apache-2.0
// The frei0r entry points of the `flarekit` filter (frei0r 1.2 API, RGBA8888). Every call is
// guarded: nothing thrown crosses into the host, a bad parameter is clamped or keeps its value
// (frei0r has no error channel; one line on stderr says so) and a failed frame passes through.
// frei0r.h declares its functions without extern "C" of its own.
extern "C" {
#include <frei0r.h>
}

#include <dlfcn.h>

#include <cstdio>
#include <filesystem>
#include <new>
#include <string>

#include "FilterSettings.h"
#include "FlareFilter.h"
#include "core/InstallPaths.h"

// Where an installed plug-in finds the shipped presets and lenses, relative to its own folder
// (PREFIX/lib/frei0r-1): CMake computes it from the install layout.
#ifndef FLAREKIT_PLUGIN_TO_PRESETS
#define FLAREKIT_PLUGIN_TO_PRESETS "../../share/flarekit/presets"
#endif
#ifndef FLAREKIT_PLUGIN_TO_MODULES
#define FLAREKIT_PLUGIN_TO_MODULES "../flarekit"
#endif

namespace {

using flarekit::frei0r::FilterParam;
using flarekit::frei0r::FlareFilter;
using flarekit::frei0r::kFilterParamCount;
using flarekit::frei0r::kFilterParams;

static_assert(std::size(kFilterParams) == std::size_t(kFilterParamCount));

//! A filter and the strings it hands back through f0r_get_param_value (frei0r lends the host a
//! pointer that must stay valid until the next call).
struct Instance {
    FlareFilter filter;
    std::string strings[kFilterParamCount];
    std::string refused[kFilterParamCount];  //!< the last value refused, said once
};

//! Each parameter's name and help as the C strings f0r_get_param_info lends the host (made once,
//! never freed: a host may keep the pointers).
struct ParamTexts {
    std::string name, help;
};
const ParamTexts& paramTexts(int index) {
    static const auto* texts = [] {
        auto* t = new ParamTexts[kFilterParamCount];
        for (int i = 0; i < kFilterParamCount; ++i)
            t[i] = {std::string(kFilterParams[i].name), std::string(kFilterParams[i].help())};
        return t;
    }();
    return texts[index];
}

bool validIndex(int index) {
    return index >= 0 && index < kFilterParamCount;
}

}  // namespace

// The entry points are what the host looks up by name: exported whatever the default visibility.
#pragma GCC visibility push(default)
extern "C" {

int f0r_init() {
    try {
        // The host is the running program: the presets are found from this plug-in's folder.
        Dl_info info{};
        if (dladdr(reinterpret_cast<void*>(&f0r_init), &info) && info.dli_fname) {
            // Through any link (~/.frei0r-1/lib/flarekit.so made by the docs' command) to the
            // installed file, whose folder the relative paths start from.
            std::error_code ec;
            std::filesystem::path file = std::filesystem::canonical(info.dli_fname, ec);
            if (ec) file = info.dli_fname;
            const std::filesystem::path dir = file.parent_path();
            flarekit::addShippedRoots(dir / FLAREKIT_PLUGIN_TO_PRESETS,
                                      dir / FLAREKIT_PLUGIN_TO_MODULES);
        }
    } catch (...) {
    }
    return 1;
}

void f0r_deinit() {}

void f0r_get_plugin_info(f0r_plugin_info_t* info) {
    info->name = "flarekit";
    info->author = "flarekit contributors";
    info->plugin_type = F0R_PLUGIN_TYPE_FILTER;
    info->color_model = F0R_COLOR_MODEL_RGBA8888;
    info->frei0r_version = FREI0R_MAJOR_VERSION;
    info->major_version = 1;
    info->minor_version = 0;
    info->num_params = kFilterParamCount;
    info->explanation =
        "Lens flares from the clip's lights: a sprite preset, the post-process chain or a lens "
        "prescription, in linear light";
}

void f0r_get_param_info(f0r_param_info_t* info, int index) {
    if (!validIndex(index)) return;
    try {
        info->name = paramTexts(index).name.c_str();
        info->type = kFilterParams[index].isString ? F0R_PARAM_STRING : F0R_PARAM_DOUBLE;
        info->explanation = paramTexts(index).help.c_str();
    } catch (...) {
        info->name = "", info->type = F0R_PARAM_DOUBLE, info->explanation = "";
    }
}

f0r_instance_t f0r_construct(unsigned int width, unsigned int height) {
    // A frame the library's image limits refuse is refused here, before any work.
    if (width == 0 || height == 0 || width > 1u << 16 || height > 1u << 16) return nullptr;
    return new (std::nothrow) Instance{FlareFilter(int(width), int(height)), {}, {}};
}

void f0r_destruct(f0r_instance_t instance) {
    delete static_cast<Instance*>(instance);
}

void f0r_set_param_value(f0r_instance_t instance, f0r_param_t param, int index) {
    if (!instance || !param || !validIndex(index)) return;
    auto* self = static_cast<Instance*>(instance);
    const FilterParam& p = kFilterParams[index];
    try {
        flarekit::frei0r::FilterSettings next = self->filter.settings();
        if (!p.isString) {
            flarekit::frei0r::setNumber(next, *p.number,
                                        *static_cast<const f0r_param_double*>(param));
        } else {
            const char* text = *static_cast<const f0r_param_string*>(param);
            const std::string value = text ? text : "";
            if (p.text) {
                next.*(p.text->member) = value;
            } else if (auto s = flarekit::frei0r::setChoice(next, *p.number, value); !s) {
                // Said once: a host such as melt sets every parameter again for each frame.
                if (self->refused[index] != value)
                    std::fprintf(stderr, "flarekit (frei0r): %s; kept '%s'\n",
                                 s.error().message.c_str(),
                                 flarekit::frei0r::choiceName(next, *p.number).c_str());
                self->refused[index] = value;
                return;
            }
        }
        self->filter.set(next);
    } catch (...) {
        std::fputs("flarekit (frei0r): a parameter could not be set; kept its value\n", stderr);
    }
}

void f0r_get_param_value(f0r_instance_t instance, f0r_param_t param, int index) {
    if (!instance || !param || !validIndex(index)) return;
    auto* self = static_cast<Instance*>(instance);
    const FilterParam& p = kFilterParams[index];
    try {
        if (!p.isString) {
            *static_cast<f0r_param_double*>(param) = p.number->get(self->filter.settings()).number;
            return;
        }
        self->strings[index] =
            p.text ? self->filter.settings().*(p.text->member)
                   : flarekit::frei0r::choiceName(self->filter.settings(), *p.number);
        *static_cast<f0r_param_string*>(param) = const_cast<char*>(self->strings[index].c_str());
    } catch (...) {
    }
}

void f0r_update(f0r_instance_t instance, double time, const uint32_t* inframe, uint32_t* outframe) {
    if (!instance || !inframe || !outframe) return;
    static_cast<Instance*>(instance)->filter.update(time, inframe, outframe);
}

}  // extern "C"
#pragma GCC visibility pop
