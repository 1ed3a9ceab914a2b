// SPDX-License-Identifier: Apache-2.0
// The engine behind flarekit.h: programs, the per-light buffers and the coverage texture,
// with the C API's calls as methods returning Status. One engine per GL context.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "flarekit/Flare.h"
#include "flarekit/Result.h"
#include "flarekit/Temporal.h"
#include "flarekit/flarekit.h"
#include "flarekit/gl/EngineScene.h"

namespace flarekit::engine {

//! The samples per side a new engine casts, and the most it takes (kEngineMeasureParams).
inline constexpr int kDefaultSamplesPerSide = EngineMeasureSettings{}.samplesPerSide;
inline constexpr int kMaxSamplesPerSide = int(kEngineMeasureParams[0].max);
inline constexpr int kDefaultTileBelow = EngineMeasureSettings{}.tileBelowSamples;
inline constexpr int kMaxTileBelow = int(kEngineMeasureParams[1].max);

class Engine {
  public:
    static Result<std::unique_ptr<Engine>> create(int maxLights);
    ~Engine();

    Result<int> loadPreset(const std::string& nameOrPath);
    Result<int> loadPresetJson(const char* json, std::size_t length);
    Status setMethod(const std::string& method);
    Status occlusion(std::span<const fk_frame> frames, const fk_light* lights, int count);
    Status draw(int view, const fk_frame* frame, const fk_light* lights, int count,
                unsigned framebuffer);
    unsigned coverageTexture() const;
    //! Raw coverage, in-frame share and filtered coverage of `view` (any may be null); the
    //! number of lights written.
    Result<int> readView(int view, float* coverage, float* inFrame, float* filtered, int count);
    Status setTransmittance(int view, unsigned texture);
    Status setGuardBand(int view, bool enabled);
    Status setOccluderCallback(fk_occluder_callback callback, void* user);
    Status setSamples(int perSide);
    Status setTileThreshold(int depthSamples);
    Status setTemporal(float attackSeconds, float releaseSeconds, float guardBand);
    Status reset();

    std::string lastError;

  private:
    struct Impl;
    explicit Engine(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

}  // namespace flarekit::engine
