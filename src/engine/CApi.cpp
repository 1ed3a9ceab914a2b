// SPDX-License-Identifier: Apache-2.0
// The C ABI of flarekit.h over engine::Engine: every call catches what the implementation
// might throw (allocation failure) and returns an error code instead; nothing unwinds into
// the application.
#include <exception>
#include <span>
#include <string>

#include "engine/Engine.h"
#include "engine/vulkan/VulkanEngine.h"
#include "flarekit/flarekit.h"
#include "flarekit/flarekit_vulkan.h"
#include "gl/GlObjects.h"

//! One engine of either backend: `engine` (OpenGL) or `vulkan`.
struct fk_engine {
    std::unique_ptr<flarekit::engine::Engine> engine;
    std::unique_ptr<flarekit::vk::VulkanEngine> vulkan;
    std::string lastError;
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
int run(fk_engine* e, const char* name, Call call) {
    try {
        flarekit::Status s = call();
        if (s) {
            e->lastError.clear();
            return 0;
        }
        e->lastError = std::string(name) + ": " + s.error().message;
        return codeOf(s.error().code);
    } catch (const std::exception& ex) {
        e->lastError = std::string(name) + ": " + ex.what();
    } catch (...) {
        e->lastError = std::string(name) + ": unexpected failure";
    }
    return kInternal;
}

//! A call of the GL backend: `call` on its engine, refused on a Vulkan engine.
template <class Call>
int guarded(fk_engine* e, const char* name, Call call, bool needsGl = true) {
    if (!e) {
        t_createError = std::string(name) + ": expected an engine, got NULL";
        return kInvalid;
    }
    if (!e->engine) {
        e->lastError = std::string(name) +
                       ": this engine is a Vulkan engine (fk_engine_create_vulkan); its passes are "
                       "recorded with fk_engine_record_occlusion and fk_engine_record_draw";
        return kInvalid;
    }
    if (needsGl && !flarekit::gl::hasCurrentContext()) {
        e->lastError = std::string(name) + ": " + kNoContext;
        return kInvalid;
    }
    return run(e, name, [&] { return call(*e->engine); });
}

//! A call both backends take: `gl` on a GL engine (no context needed), `vulkan` on the other.
template <class GlCall, class VulkanCall>
int either(fk_engine* e, const char* name, GlCall gl, VulkanCall vulkan, bool glNeedsGl = false) {
    if (e && !e->engine) return run(e, name, [&] { return vulkan(*e->vulkan); });
    return guarded(e, name, gl, glNeedsGl);
}

//! A preset from a name, a path or (json non-null) JSON text: for a Vulkan engine.
flarekit::Result<int> vulkanPreset(flarekit::vk::VulkanEngine& v, const char* nameOrPath,
                                   const char* json, std::size_t length) {
    auto preset = json ? flarekit::parsePreset(std::string(json, length), "json")
                       : flarekit::loadPreset(nameOrPath);
    if (!preset) return preset.error();
    return v.addPreset(std::move(*preset));
}

}  // namespace

namespace {
//! A call of the Vulkan backend, refused on a GL engine.
template <class Call>
int vulkanOnly(fk_engine* e, const char* name, Call call) {
    if (!e) {
        t_createError = std::string(name) + ": expected an engine, got NULL";
        return kInvalid;
    }
    if (!e->vulkan) {
        e->lastError = std::string(name) +
                       ": this engine is an OpenGL engine (fk_engine_create); expected one from "
                       "fk_engine_create_vulkan";
        return kInvalid;
    }
    return run(e, name, [&] { return call(*e->vulkan); });
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
        return new fk_engine{std::move(*engine), nullptr, {}};
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
    if (e->engine && !flarekit::gl::hasCurrentContext()) (void)e->engine.release();
    delete e;
}

const char* fk_error(const fk_engine* e) {
    return e ? e->lastError.c_str() : t_createError.c_str();
}

int fk_engine_load_preset(fk_engine* e, const char* name_or_path) {
    int id = kInvalid;
    const auto take = [&](flarekit::Result<int> loaded) {
        if (!loaded) return flarekit::Status(loaded.error());
        id = *loaded;
        return flarekit::Status(flarekit::Ok{});
    };
    const auto noName = [] {
        return flarekit::Status(
            flarekit::invalidInput("name_or_path: expected a preset name or path, got NULL"));
    };
    const int rc = either(
        e, "fk_engine_load_preset",
        [&](flarekit::engine::Engine& en) {
            return name_or_path ? take(en.loadPreset(name_or_path)) : noName();
        },
        [&](flarekit::vk::VulkanEngine& v) {
            return name_or_path ? take(vulkanPreset(v, name_or_path, nullptr, 0)) : noName();
        },
        true);
    return rc < 0 ? rc : id;
}

int fk_engine_load_preset_json(fk_engine* e, const char* json, size_t length) {
    int id = kInvalid;
    const auto take = [&](flarekit::Result<int> loaded) {
        if (!loaded) return flarekit::Status(loaded.error());
        id = *loaded;
        return flarekit::Status(flarekit::Ok{});
    };
    const int rc = either(
        e, "fk_engine_load_preset_json",
        [&](flarekit::engine::Engine& en) { return take(en.loadPresetJson(json, length)); },
        [&](flarekit::vk::VulkanEngine& v) {
            if (!json)
                return flarekit::Status(
                    flarekit::invalidInput("json: expected preset JSON text, got NULL"));
            return take(vulkanPreset(v, nullptr, json, length));
        });
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
    return e && e->engine ? e->engine->coverageTexture() : 0u;
}

int fk_engine_read_view(fk_engine* e, int view, float* coverage, float* in_frame, float* filtered,
                        int count) {
    int n = 0;
    const auto take = [&](flarekit::Result<int> r) {
        if (!r) return flarekit::Status(r.error());
        n = *r;
        return flarekit::Status(flarekit::Ok{});
    };
    const int rc = either(
        e, "fk_engine_read_view",
        [&](flarekit::engine::Engine& en) {
            return take(en.readView(view, coverage, in_frame, filtered, count));
        },
        [&](flarekit::vk::VulkanEngine& v) {
            return take(v.readView(view, coverage, in_frame, filtered, count));
        },
        true);
    return rc < 0 ? rc : n;
}

int fk_engine_read_coverage(fk_engine* e, float* out, int count) {
    int n = 0;
    const auto take = [&](flarekit::Result<int> r) {
        if (!r) return flarekit::Status(r.error());
        n = *r;
        return flarekit::Status(flarekit::Ok{});
    };
    const auto noOut = [] {
        return flarekit::Status(
            flarekit::invalidInput("out: expected an array of count floats, got NULL"));
    };
    const int rc = either(
        e, "fk_engine_read_coverage",
        [&](flarekit::engine::Engine& en) {
            return count > 0 && !out ? noOut() : take(en.readView(0, out, nullptr, nullptr, count));
        },
        [&](flarekit::vk::VulkanEngine& v) {
            return count > 0 && !out ? noOut() : take(v.readView(0, out, nullptr, nullptr, count));
        },
        true);
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
    return either(
        e, "fk_engine_set_guard_band",
        [&](flarekit::engine::Engine& en) { return en.setGuardBand(view, enabled != 0); },
        [&](flarekit::vk::VulkanEngine& v) { return v.setGuardBand(view, enabled != 0); });
}

int fk_engine_set_tile_threshold(fk_engine* e, int depth_samples) {
    return either(
        e, "fk_engine_set_tile_threshold",
        [&](flarekit::engine::Engine& en) { return en.setTileThreshold(depth_samples); },
        [&](flarekit::vk::VulkanEngine& v) { return v.setTileThreshold(depth_samples); });
}

int fk_engine_set_samples(fk_engine* e, int samples_per_side) {
    return either(
        e, "fk_engine_set_samples",
        [&](flarekit::engine::Engine& en) { return en.setSamples(samples_per_side); },
        [&](flarekit::vk::VulkanEngine& v) { return v.setSamples(samples_per_side); });
}

int fk_engine_set_temporal(fk_engine* e, float attack_seconds, float release_seconds,
                           float guard_band) {
    return either(
        e, "fk_engine_set_temporal",
        [&](flarekit::engine::Engine& en) {
            return en.setTemporal(attack_seconds, release_seconds, guard_band);
        },
        [&](flarekit::vk::VulkanEngine& v) {
            return v.setTemporal(attack_seconds, release_seconds, guard_band);
        });
}

int fk_engine_reset(fk_engine* e) {
    return either(
        e, "fk_engine_reset", [&](flarekit::engine::Engine& en) { return en.reset(); },
        [&](flarekit::vk::VulkanEngine& v) { return v.reset(); }, true);
}

fk_engine* fk_engine_create_vulkan(const fk_vulkan_device* device, int max_lights) {
    try {
        if (!device) {
            t_createError =
                "fk_engine_create_vulkan: device: expected an fk_vulkan_device, got NULL";
            return nullptr;
        }
        auto engine = flarekit::vk::VulkanEngine::create(*device, max_lights);
        if (!engine) {
            t_createError = "fk_engine_create_vulkan: " + engine.error().message;
            return nullptr;
        }
        t_createError.clear();
        return new fk_engine{nullptr, std::move(*engine), {}};
    } catch (const std::exception& ex) {
        t_createError = std::string("fk_engine_create_vulkan: ") + ex.what();
    } catch (...) {
        t_createError = "fk_engine_create_vulkan: unexpected failure";
    }
    return nullptr;
}

int fk_engine_record_occlusion(fk_engine* e, const fk_vulkan_frame* vk, const fk_frame* frame,
                               const fk_light* lights, int count) {
    return vulkanOnly(e, "fk_engine_record_occlusion", [&](flarekit::vk::VulkanEngine& v) {
        return v.recordOcclusion(0, vk, frame, lights, count);
    });
}

int fk_engine_record_draw(fk_engine* e, const fk_vulkan_frame* vk, const fk_frame* frame,
                          const fk_light* lights, int count) {
    return vulkanOnly(e, "fk_engine_record_draw", [&](flarekit::vk::VulkanEngine& v) {
        return v.recordDraw(0, vk, frame, lights, count);
    });
}

int fk_engine_set_vulkan_occluder_callback(fk_engine* e, fk_vulkan_occluder_callback callback,
                                           void* user) {
    return vulkanOnly(
        e, "fk_engine_set_vulkan_occluder_callback",
        [&](flarekit::vk::VulkanEngine& v) { return v.setOccluderCallback(callback, user); });
}

VkImageView fk_engine_coverage_view(const fk_engine* e) {
    return e && e->vulkan ? e->vulkan->coverageView() : VK_NULL_HANDLE;
}

}  // extern "C"
