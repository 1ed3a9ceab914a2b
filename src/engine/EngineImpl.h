// SPDX-License-Identifier: Apache-2.0
// The state behind engine::Engine, shared by its three files: Engine.cpp (set-up and the
// batched occlusion pass), EngineTextureMask.cpp (the sun-map method) and EngineDraw.cpp (the
// instanced flares).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "engine/Engine.h"
#include "engine/EngineInput.h"
#include "engine/EnginePrograms.h"
#include "engine/SunMaps.h"
#include "flare/ElementSprites.h"
#include "flarekit/Flare.h"

namespace flarekit::engine {

//! Light buffers written in turn, so a call's upload does not wait for the GPU to finish
//! reading the previous frame's lights (three: a frame being drawn, one queued, one filled).
inline constexpr int kLightRing = 3;
inline constexpr GLsizeiptr kLightBytes = 16 * sizeof(float);

struct LoadedPreset {
    Preset preset;
    int spriteHeight = 0;  //!< frame height the sprites were made for (0: none yet)
    std::vector<ElementSprite> sprites;
};

//! Where the samples of an n-sample pixel sit (glGetMultisamplefv), per sample count.
struct SamplePattern {
    int samples = 0;
    std::array<float, 32> positions{};
};

struct Engine::Impl {
    int maxLights = 0;
    CoverageProgram coverage[2];  //!< single-sample depth, multisampled depth
    SunMapProgram sunMap;
    bool textureMask = false;  //!< the method: texture-mask (sun maps) instead of compute
    fk_occluder_callback occluders = nullptr;
    void* occludersUser = nullptr;
    std::optional<SunMapAtlas> sunMaps;  //!< made when texture-mask is chosen
    FlareProgram flare;
    std::array<gl::Buffer, kLightRing> lightBuffers;
    int ringAt = 0;
    gl::Buffer state;           //!< vec4 per light and view (light_coverage.comp)
    gl::Buffer tiles;           //!< int per light and view: its sun-map tile or -1
    std::vector<int> tileOf;    //!< one view's `tiles`, as uploaded
    gl::Texture coverageImage;  //!< R32F, maxLights x FK_MAX_VIEWS: filtered coverage
    gl::VertexArray vertexArray;
    gl::Framebuffer probe;  //!< for asking where a multisampled texture's samples are
    Sampler nearest, linear;
    std::vector<LoadedPreset> presets;
    std::vector<SamplePattern> patterns;
    std::array<GLuint, FK_MAX_VIEWS> transmittance{};
    std::array<bool, FK_MAX_VIEWS> guardBand{};
    int samplesPerSide = kDefaultSamplesPerSide;
    int tileBelow = kDefaultTileBelow;
    TemporalParams temporal;
    int lastViews = 0;
    std::array<int, FK_MAX_VIEWS> lastCount{};
    std::vector<float> packed;  //!< the lights as uploaded, kept to reuse its memory

    GLuint uploadLights(const fk_light* lights, int count);
    const SamplePattern& patternFor(GLuint texture, int samples);
    Status ensureSprites(LoadedPreset& p, int height);
    //! Which lights of view `view` sun-map tiles measure (tileOf, uploaded to `tiles`): all
    //! with texture-mask, those under tileBelow depth samples with compute and a callback.
    //! Returns how many.
    int assignTiles(int view, const fk_frame& f, int depthSamples, const fk_light* lights,
                    int count);
    Status measureSunMaps(int view, const fk_frame& f, const fk_light* lights, int count,
                          GLuint lightBuffer);
    void measureDepth(int view, const fk_frame& f, const DepthTextureInfo& depth, int count,
                      GLuint lightBuffer);
};

}  // namespace flarekit::engine
