// SPDX-License-Identifier: Apache-2.0
// The C ABI of flarekit.h's any-renderer part over engine::FlareSet, and the exported shaders:
// no GL is touched; every call catches what the implementation might throw and returns an
// error code instead.
#include <algorithm>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "engine/FlareSet.h"
#include "flarekit/flarekit.h"
#include "flarekit_exported_shaders.h"

struct fk_flare_set {
    flarekit::engine::FlareSet set;
    std::vector<fk_flare_instance> scratch;  //!< the last call's records, memory kept
};

namespace {

thread_local std::string t_createError;

int codeOf(flarekit::ErrorCode code) {
    return code == flarekit::ErrorCode::Internal ? FK_ERROR_INTERNAL : FK_ERROR_INVALID;
}

//! Runs `call`, turning a Status or an exception into the C return code and the set's error.
template <class Call>
int guarded(const fk_flare_set* s, const char* name, Call call) {
    if (!s) {
        t_createError = std::string(name) + ": expected a flare set, got NULL";
        return FK_ERROR_INVALID;
    }
    std::string& error = const_cast<fk_flare_set*>(s)->set.lastError;
    try {
        flarekit::Status st = call();
        if (st) {
            error.clear();
            return 0;
        }
        error = std::string(name) + ": " + st.error().message;
        return codeOf(st.error().code);
    } catch (const std::exception& ex) {
        error = std::string(name) + ": " + ex.what();
    } catch (...) {
        error = std::string(name) + ": unexpected failure";
    }
    return FK_ERROR_INTERNAL;
}

//! A Result<int> call: its value, or the error code.
template <class Call>
int counted(fk_flare_set* s, const char* name, Call call) {
    int value = 0;
    const int rc = guarded(s, name, [&] {
        auto r = call();
        if (!r) return flarekit::Status(r.error());
        value = *r;
        return flarekit::Status(flarekit::Ok{});
    });
    return rc < 0 ? rc : value;
}

struct Exported {
    const unsigned char* bytes;
    std::size_t size;
};

}  // namespace

extern "C" {

fk_flare_set* fk_flare_set_create(void) {
    try {
        t_createError.clear();
        return new fk_flare_set;
    } catch (...) {
        t_createError = "fk_flare_set_create: out of memory";
    }
    return nullptr;
}

void fk_flare_set_destroy(fk_flare_set* s) {
    delete s;
}

const char* fk_flare_set_error(const fk_flare_set* s) {
    return s ? s->set.lastError.c_str() : t_createError.c_str();
}

int fk_flare_set_load_preset(fk_flare_set* s, const char* name_or_path) {
    return counted(s, "fk_flare_set_load_preset", [&]() -> flarekit::Result<int> {
        if (!name_or_path)
            return flarekit::invalidInput("name_or_path: expected a preset name or path, got NULL");
        return s->set.loadPreset(name_or_path);
    });
}

int fk_flare_set_load_preset_json(fk_flare_set* s, const char* json, size_t length) {
    return counted(s, "fk_flare_set_load_preset_json",
                   [&] { return s->set.loadPresetJson(json, length); });
}

int fk_flare_set_prepare(fk_flare_set* s, int frame_height) {
    return counted(s, "fk_flare_set_prepare", [&] { return s->set.prepare(frame_height); });
}

int fk_flare_set_texture(const fk_flare_set* s, int slot, int* width, int* height, float* rgba) {
    return guarded(s, "fk_flare_set_texture", [&]() -> flarekit::Status {
        const flarekit::SpriteImage* sprite = s->set.sprite(slot);
        if (!sprite) {
            return flarekit::invalidInput(
                "slot: expected a slot of the last "
                "fk_flare_set_prepare, got " +
                std::to_string(slot));
        }
        if (!width || !height)
            return flarekit::invalidInput("width, height: expected two int pointers, got NULL");
        const flarekit::Image& image = sprite->image;
        *width = image.width();
        *height = image.height();
        if (rgba)
            std::copy(image.data(), image.data() + std::size_t(image.width()) * image.height() * 4,
                      rgba);
        return flarekit::Ok{};
    });
}

int fk_flare_set_instances(fk_flare_set* s, const fk_frame* frame, const fk_light* lights,
                           const float* coverage, int count, float edge_fade,
                           fk_flare_instance* out, int capacity) {
    return counted(s, "fk_flare_set_instances", [&]() -> flarekit::Result<int> {
        if (capacity < 0 || (capacity > 0 && !out)) {
            return flarekit::invalidInput(
                "out, capacity: expected an array of capacity records (or NULL and 0), got " +
                std::string(out ? "an array" : "NULL") + " and " + std::to_string(capacity));
        }
        if (flarekit::Status st =
                s->set.instances(frame, lights, coverage, count, edge_fade, s->scratch);
            !st)
            return st.error();
        const std::size_t n = std::min(s->scratch.size(), std::size_t(capacity));
        std::copy(s->scratch.begin(), s->scratch.begin() + std::ptrdiff_t(n), out);
        return int(s->scratch.size());
    });
}

const void* fk_flare_shader(fk_shader_language language, fk_shader_stage stage, size_t* size) {
    namespace x = flarekit::exported;
    // Indexed [language][stage], as the enums count.
    static const Exported table[4][2] = {
        {{x::flare_instance_vert, x::flare_instance_vert_size},
         {x::flare_instance_frag, x::flare_instance_frag_size}},
        {{x::flare_instance_vert_spv, x::flare_instance_vert_spv_size},
         {x::flare_instance_frag_spv, x::flare_instance_frag_spv_size}},
        {{x::flare_instance_vert_hlsl, x::flare_instance_vert_hlsl_size},
         {x::flare_instance_frag_hlsl, x::flare_instance_frag_hlsl_size}},
        {{x::flare_instance_vert_metal, x::flare_instance_vert_metal_size},
         {x::flare_instance_frag_metal, x::flare_instance_frag_metal_size}},
    };
    int l = 0, st = 0;  // read as int: a C caller may store any int in an enum
    std::memcpy(&l, &language, sizeof l);
    std::memcpy(&st, &stage, sizeof st);
    if (l < 0 || l > 3 || st < 0 || st > 1) {
        if (size) *size = 0;
        return nullptr;
    }
    const Exported& e = table[l][st];
    if (size) *size = e.size;
    return e.bytes;
}

}  // extern "C"
