// SPDX-License-Identifier: Apache-2.0
// The C++ face of flarekit.h: an owning, move-only Engine whose calls throw nothing and
// return a flarekit::Outcome (false with the message on failure), over the same C functions,
// so a C++ engine links the same libflarekit.so as C, C# or Rust callers.
#pragma once

#include <span>
#include <string>
#include <utility>

#include "flarekit/flarekit.h"

namespace flarekit::api {

//! A call's result: ok, or the engine's one-line error.
struct Outcome {
    bool ok = true;
    std::string error;
    explicit operator bool() const { return ok; }
};

class Engine {
  public:
    //! An engine for max_lights lights; check valid() (and createError()) before use.
    explicit Engine(int maxLights) : m_engine(fk_engine_create(maxLights)) {
        if (!m_engine) m_createError = fk_error(nullptr);
    }
    ~Engine() { fk_engine_destroy(m_engine); }
    Engine(Engine&& o) noexcept
        : m_engine(std::exchange(o.m_engine, nullptr)), m_createError(std::move(o.m_createError)) {}
    Engine& operator=(Engine&& o) noexcept {
        if (this != &o) {
            fk_engine_destroy(m_engine);
            m_engine = std::exchange(o.m_engine, nullptr);
            m_createError = std::move(o.m_createError);
        }
        return *this;
    }
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    bool valid() const { return m_engine != nullptr; }
    const std::string& createError() const { return m_createError; }
    fk_engine* handle() const { return m_engine; }

    //! The preset's id (>= 0), or -1 with `error` set.
    int loadPreset(const std::string& nameOrPath, std::string* error = nullptr) {
        const int id = fk_engine_load_preset(m_engine, nameOrPath.c_str());
        if (id < 0 && error) *error = fk_error(m_engine);
        return id;
    }
    Outcome setMethod(const std::string& method) {
        return outcome(fk_engine_set_method(m_engine, method.c_str()));
    }
    Outcome occlusion(const fk_frame& frame, std::span<const fk_light> lights) {
        return outcome(fk_engine_occlusion(m_engine, &frame, lights.data(), int(lights.size())));
    }
    Outcome occlusion(std::span<const fk_frame> views, std::span<const fk_light> lights) {
        return outcome(fk_engine_occlusion_views(m_engine, views.data(), int(views.size()),
                                                 lights.data(), int(lights.size())));
    }
    Outcome draw(const fk_frame& frame, std::span<const fk_light> lights, unsigned framebuffer,
                 int view = 0) {
        return outcome(fk_engine_draw_view(m_engine, view, &frame, lights.data(),
                                           int(lights.size()), framebuffer));
    }
    unsigned coverageTexture() const { return fk_engine_coverage_texture(m_engine); }
    //! Raw coverage of view 0's lights into `out` (waits for the GPU): how many were written.
    int readCoverage(std::span<float> out) {
        return fk_engine_read_coverage(m_engine, out.data(), int(out.size()));
    }
    Outcome setTransmittance(int view, unsigned texture) {
        return outcome(fk_engine_set_transmittance(m_engine, view, texture));
    }
    Outcome setSamples(int perSide) { return outcome(fk_engine_set_samples(m_engine, perSide)); }
    Outcome setTileThreshold(int depthSamples) {
        return outcome(fk_engine_set_tile_threshold(m_engine, depthSamples));
    }
    Outcome setTemporal(float attack, float release, float guardBand) {
        return outcome(fk_engine_set_temporal(m_engine, attack, release, guardBand));
    }
    Outcome reset() { return outcome(fk_engine_reset(m_engine)); }

  private:
    Outcome outcome(int rc) const {
        if (rc >= 0) return {};
        return {false, fk_error(m_engine)};
    }
    fk_engine* m_engine = nullptr;
    std::string m_createError;
};

}  // namespace flarekit::api
