// SPDX-License-Identifier: Apache-2.0
// The uniform blocks the engine's shaders declare under VULKAN (backend.glsl's UNIFORMS_BEGIN),
// laid out as std140 puts them; each offset is the one SPIRV-Cross reflects from the SPIR-V.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine/vulkan/VulkanApi.h"

namespace flarekit::vk {

struct ViewParams {  // light_view.glsl, binding 0
    float viewMatrix[16];
    float projectionMatrix[16];
    std::int32_t viewport[4];
    float depthTextureSize[2];
    std::int32_t depthConvention;
    std::uint32_t depthPastViewport;
};
static_assert(offsetof(ViewParams, viewport) == 128 &&
              offsetof(ViewParams, depthConvention) == 152 && sizeof(ViewParams) == 160);

struct StateParams {  // light_state.glsl, binding 10
    std::int32_t viewIndex, stateBase;
    float attackStep, releaseStep;
};
static_assert(sizeof(StateParams) == 16);

struct CoverageParams {  // light_coverage.comp, binding 11
    std::int32_t perSide, samplesPerPixel;
    std::uint32_t hasTransmittance;
    std::int32_t sampleCount;
    float samplePositions[16][4];  // std140: each vec2 of the array takes 16 bytes
};
static_assert(offsetof(CoverageParams, samplePositions) == 16 && sizeof(CoverageParams) == 272);

struct FlareParams {  // light_flare.vert, binding 12
    std::int32_t coverageChannel;
    std::uint32_t fadeAtEdges;
    std::int32_t viewIndex;
    float guardBand, referenceFlux;
};
static_assert(sizeof(FlareParams) == 20);

struct ElementParams {  // light_flare.vert, binding 13
    float halfSize[2];
    std::int32_t presetId;
    float t;
    std::uint32_t edgeStreak;
    float reach;
};
static_assert(offsetof(ElementParams, presetId) == 8 && sizeof(ElementParams) == 24);

struct SunMapParams {  // sunmap_coverage.comp, binding 11
    std::int32_t tileSize, tilesPerRow;
};

//! Where each view's blocks sit in the engine's parameter buffer: 256-byte aligned, the
//! largest minUniformBufferOffsetAlignment Vulkan allows.
inline constexpr VkDeviceSize kViewParamsAt = 0, kStateParamsAt = 256, kCoverageParamsAt = 512,
                              kFlareParamsAt = 1024, kSunMapParamsAt = 1536, kParamsPerView = 2048;

}  // namespace flarekit::vk
