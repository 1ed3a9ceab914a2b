// SPDX-License-Identifier: Apache-2.0
// Checks of everything an application hands the engine API, before any GL work: each error
// names the argument and says what was expected ("frames[1].viewport: expected ..."), so a
// refused call draws nothing and leaves no GL error.
#pragma once

#include <string>
#include <vector>

#include "flarekit/Result.h"
#include "flarekit/Temporal.h"
#include "flarekit/flarekit.h"

namespace flarekit::engine {

//! What the engine learnt of a frame's depth texture while checking it.
struct DepthTextureInfo {
    bool multisample = false;
    int samples = 1;
};

//! The frame's numbers (viewport inside the texture, finite matrices, dt, convention) and its
//! depth texture (a 2D or 2D multisample texture of that size with a depth format); `at` is
//! the argument's name for messages.
Result<DepthTextureInfo> checkFrame(const fk_frame* frame, const std::string& at);
//! The frame's numbers alone (no GL): what drawing or instance data needs of it.
Status checkFrameNumbers(const fk_frame* frame, const std::string& at);

//! count in [0, maxLights], every light's type, finite position / direction, positive radius
//! (directional: at most 45 degrees), non-negative colour and intensity, preset -1 or a
//! loaded id.
Status checkLights(const fk_light* lights, int count, int maxLights, int presetCount);

//! The lights as the shaders' Light records (light_view.glsl): 16 floats each, directional
//! radii turned into radians. `packed` is resized to count x 16.
void packLights(const fk_light* lights, int count, std::vector<float>& packed);

//! samples_per_side in 1..kMaxSamplesPerSide (fk_engine_set_samples).
Status checkSamplesPerSide(int perSide);

//! `t` with the filter's time constants and edge-fade width replaced, if they are valid
//! (fk_engine_set_temporal); `t` is left as it was otherwise.
Status setTemporalParams(TemporalParams& t, float attackSeconds, float releaseSeconds,
                         float guardBand);

//! A view index: 0..FK_MAX_VIEWS - 1.
Status checkView(int view);

//! A framebuffer name the application owns: 0 (the default one) or a complete framebuffer.
Status checkFramebuffer(unsigned framebuffer);

}  // namespace flarekit::engine
