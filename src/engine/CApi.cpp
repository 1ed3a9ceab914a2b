// SPDX-License-Identifier: Apache-2.0
// The C ABI of flarekit.h over engine::Engine: every call catches what the implementation
// might throw (allocation failure) and returns an error code instead; nothing unwinds into
// the application.
#include <exception>
#include <span>
#include <string>

#include "engine/Engine.h"
#include "flarekit/flarekit.h"
#include "gl/GlObjects.h"

struct fk_engine {
    std::unique_ptr<flarekit::engine::Engine> engine;
};

namespace {

//! fk_error(NULL): why the last fk_engine_create of this thread failed.
thread_local std::string t_createError;

constexpr int kInvalid = FK_ERROR_INVALID;  //!< a refused argument (fk_error says which)
constexpr const char* kNoContext =
    "no OpenGL context is current on this thread (the application's GL 4.5 core context must be "
    "current in every call)";
constexpr int kInternal = FK_ERROR_INTERNAL;  //!< a failure inside flarekit or the GL driver

//! The C code of a library error: the one place the C API's codes come from Result's.
int codeOf(flarekit::ErrorCode code) {
    switch (code) {
        case flarekit::ErrorCode::InvalidInput:
        case flarekit::ErrorCode::Io:
            return FK_ERROR_INVALID;
        case flarekit::ErrorCode::Interrupted:
            return FK_ERROR_INTERRUPTED;
        case flarekit::ErrorCode::Internal:
            break;
    }
    return FK_ERROR_INTERNAL;
}

//! Runs `call` on the engine, turning a Status or an exception into the C return code and
//! fk_error's text. Calls that touch GL first check a context is current: without one,
//! libepoxy would end the process instead of the call returning an error.
template <class Call>
int guarded(fk_engine* e, const char* name, Call call, bool needsGl = true) {
    if (!e) {
        t_createError = std::string(name) + ": expected an engine, got NULL";
        return kInvalid;
    }
    if (needsGl && !flarekit::gl::hasCurrentContext()) {
        e->engine->lastError = std::string(name) + ": " + kNoContext;
        return kInvalid;
    }
    try {
        flarekit::Status s = call(*e->engine);
        if (s) {
            e->engine->lastError.clear();
            return 0;
        }
        e->engine->lastError = std::string(name) + ": " + s.error().message;
        return codeOf(s.error().code);
    } catch (const std::exception& ex) {
        e->engine->lastError = std::string(name) + ": " + ex.what();
    } catch (...) {
        e->engine->lastError = std::string(name) + ": unexpected failure";
    }
    return kInternal;
}

}  // namespace

extern "C" {

fk_engine* fk_engine_create(int max_lights) {
    try {
        auto engine = flarekit::engine::Engine::create(max_lights);
        if (!engine) {
            t_createError = "fk_engine_create: " + engine.error().message;
            return nullptr;
        }
        t_createError.clear();
        return new fk_engine{std::move(*engine)};
    } catch (const std::exception& ex) {
        t_createError = std::string("fk_engine_create: ") + ex.what();
    } catch (...) {
        t_createError = "fk_engine_create: unexpected failure";
    }
    return nullptr;
}

void fk_engine_destroy(fk_engine* e) {
    if (!e) return;
    // Without the engine's context current its GL objects cannot be deleted (libepoxy would
    // abort the process): they are left to the context's own destruction.
    if (!flarekit::gl::hasCurrentContext()) (void)e->engine.release();
    delete e;
}

const char* fk_error(const fk_engine* e) {
    return e ? e->engine->lastError.c_str() : t_createError.c_str();
}

int fk_engine_load_preset(fk_engine* e, const char* name_or_path) {
    int id = kInvalid;
    const int rc = guarded(e, "fk_engine_load_preset", [&](flarekit::engine::Engine& en) {
        if (!name_or_path)
            return flarekit::Status(
                flarekit::invalidInput("name_or_path: expected a preset "
                                       "name or path, got NULL"));
        auto loaded = en.loadPreset(name_or_path);
        if (!loaded) return flarekit::Status(loaded.error());
        id = *loaded;
        return flarekit::Status(flarekit::Ok{});
    });
    return rc < 0 ? rc : id;
}

int fk_engine_load_preset_json(fk_engine* e, const char* json, size_t length) {
    int id = kInvalid;
    const int rc = guarded(
        e, "fk_engine_load_preset_json",
        [&](flarekit::engine::Engine& en) {
            auto loaded = en.loadPresetJson(json, length);
            if (!loaded) return flarekit::Status(loaded.error());
            id = *loaded;
            return flarekit::Status(flarekit::Ok{});
        },
        false);
    return rc < 0 ? rc : id;
}

int fk_engine_set_method(fk_engine* e, const char* method) {
    return guarded(e, "fk_engine_set_method", [&](flarekit::engine::Engine& en) {
        return en.setMethod(method ? method : "(NULL)");
    });
}

int fk_engine_occlusion(fk_engine* e, const fk_frame* frame, const fk_light* lights, int count) {
    return guarded(e, "fk_engine_occlusion", [&](flarekit::engine::Engine& en) {
        if (!frame)
            return flarekit::Status(flarekit::invalidInput("frame: expected a frame, got NULL"));
        return en.occlusion(std::span<const fk_frame>(frame, 1), lights, count);
    });
}

int fk_engine_occlusion_views(fk_engine* e, const fk_frame* frames, int views,
                              const fk_light* lights, int count) {
    return guarded(e, "fk_engine_occlusion_views", [&](flarekit::engine::Engine& en) {
        if (!frames)
            return flarekit::Status(
                flarekit::invalidInput("frames: expected an array of views, got NULL"));
        if (views < 1 || views > FK_MAX_VIEWS) {
            return flarekit::Status(flarekit::invalidInput("views: expected 1.." +
                                                           std::to_string(FK_MAX_VIEWS) + ", got " +
                                                           std::to_string(views)));
        }
        return en.occlusion(std::span<const fk_frame>(frames, std::size_t(views)), lights, count);
    });
}

unsigned fk_engine_coverage_texture(const fk_engine* e) {
    return e ? e->engine->coverageTexture() : 0u;
}

int fk_engine_read_view(fk_engine* e, int view, float* coverage, float* in_frame, float* filtered,
                        int count) {
    int n = 0;
    const int rc = guarded(e, "fk_engine_read_view", [&](flarekit::engine::Engine& en) {
        auto r = en.readView(view, coverage, in_frame, filtered, count);
        if (!r) return flarekit::Status(r.error());
        n = *r;
        return flarekit::Status(flarekit::Ok{});
    });
    return rc < 0 ? rc : n;
}

int fk_engine_read_coverage(fk_engine* e, float* out, int count) {
    int n = 0;
    const int rc = guarded(e, "fk_engine_read_coverage", [&](flarekit::engine::Engine& en) {
        if (count > 0 && !out) {
            return flarekit::Status(
                flarekit::invalidInput("out: expected an array of count floats, got NULL"));
        }
        auto r = en.readView(0, out, nullptr, nullptr, count);
        if (!r) return flarekit::Status(r.error());
        n = *r;
        return flarekit::Status(flarekit::Ok{});
    });
    return rc < 0 ? rc : n;
}

int fk_engine_draw(fk_engine* e, const fk_frame* frame, const fk_light* lights, int count,
                   unsigned framebuffer) {
    return guarded(e, "fk_engine_draw", [&](flarekit::engine::Engine& en) {
        return en.draw(0, frame, lights, count, framebuffer);
    });
}

int fk_engine_draw_view(fk_engine* e, int view, const fk_frame* frame, const fk_light* lights,
                        int count, unsigned framebuffer) {
    return guarded(e, "fk_engine_draw_view", [&](flarekit::engine::Engine& en) {
        return en.draw(view, frame, lights, count, framebuffer);
    });
}

int fk_engine_set_transmittance(fk_engine* e, int view, unsigned texture) {
    return guarded(e, "fk_engine_set_transmittance", [&](flarekit::engine::Engine& en) {
        return en.setTransmittance(view, texture);
    });
}

int fk_engine_set_occluder_callback(fk_engine* e, fk_occluder_callback callback, void* user) {
    return guarded(
        e, "fk_engine_set_occluder_callback",
        [&](flarekit::engine::Engine& en) { return en.setOccluderCallback(callback, user); },
        false);
}

int fk_engine_set_guard_band(fk_engine* e, int view, int enabled) {
    return guarded(
        e, "fk_engine_set_guard_band",
        [&](flarekit::engine::Engine& en) { return en.setGuardBand(view, enabled != 0); }, false);
}

int fk_engine_set_tile_threshold(fk_engine* e, int depth_samples) {
    return guarded(
        e, "fk_engine_set_tile_threshold",
        [&](flarekit::engine::Engine& en) { return en.setTileThreshold(depth_samples); }, false);
}

int fk_engine_set_samples(fk_engine* e, int samples_per_side) {
    return guarded(
        e, "fk_engine_set_samples",
        [&](flarekit::engine::Engine& en) { return en.setSamples(samples_per_side); }, false);
}

int fk_engine_set_temporal(fk_engine* e, float attack_seconds, float release_seconds,
                           float guard_band) {
    return guarded(
        e, "fk_engine_set_temporal",
        [&](flarekit::engine::Engine& en) {
            return en.setTemporal(attack_seconds, release_seconds, guard_band);
        },
        false);
}

int fk_engine_reset(fk_engine* e) {
    return guarded(e, "fk_engine_reset", [&](flarekit::engine::Engine& en) { return en.reset(); });
}

}  // extern "C"
