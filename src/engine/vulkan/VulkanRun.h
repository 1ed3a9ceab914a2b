// SPDX-License-Identifier: Apache-2.0
// `--backend vulkan` of `flarekit lights` and `flarekit visibility --method compute`: the
// scene rendered by flarekit's GL renderer (its colour and transmittance), its depth drawn
// again by a Vulkan host as a Vulkan application's depth pass (and its objects into the small
// lights' sun maps by the Vulkan occluder callback), and every light measured and drawn through
// fk_engine_record_occlusion and fk_engine_record_draw.
#pragma once

#include <array>

#include "flarekit/gl/EngineRun.h"

namespace flarekit::vk {

//! projection x view of a frame, column-major (what a depth pass draws with).
std::array<float, 16> viewProjection(const fk_frame& f);

//! runEngineScene's Vulkan half: `renderer` has drawn `scene` (its GL context current).
Result<EngineRun> runEngineSceneOnVulkan(const Scene& scene, const EngineRunOptions& options,
                                         const SceneRenderer& renderer);

}  // namespace flarekit::vk
