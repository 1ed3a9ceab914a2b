// SPDX-License-Identifier: Apache-2.0
// The engine API's Vulkan backend (flarekit_vulkan.h): the GL backend's shaders compiled to
// SPIR-V at build time, recording the batched occlusion pass and the instanced flares into
// the application's command buffers. Its settings (presets, samples, temporal filter, guard
// band) are the GL engine's; what differs is how each pass reaches the GPU.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "engine/vulkan/VulkanApi.h"
#include "flarekit/Flare.h"
#include "flarekit/Result.h"
#include "flarekit/Temporal.h"
#include "flarekit/flarekit_vulkan.h"

namespace flarekit::vk {

class VulkanEngine {
  public:
    static Result<std::unique_ptr<VulkanEngine>> create(const fk_vulkan_device& device,
                                                        int maxLights);
    ~VulkanEngine();

    Result<int> addPreset(Preset preset);
    Status setSamples(int perSide);
    Status setTemporal(float attackSeconds, float releaseSeconds, float guardBand);
    Status setGuardBand(int view, bool enabled);
    Status setTileThreshold(int depthSamples);
    Status setOccluderCallback(fk_vulkan_occluder_callback callback, void* user);
    Status reset();
    Status recordOcclusion(int view, const fk_vulkan_frame* vk, const fk_frame* frame,
                           const fk_light* lights, int count);
    Status recordDraw(int view, const fk_vulkan_frame* vk, const fk_frame* frame,
                      const fk_light* lights, int count);
    Result<int> readView(int view, float* coverage, float* inFrame, float* filtered, int count);
    VkImageView coverageView() const;

  private:
    struct Impl;
    explicit VulkanEngine(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

}  // namespace flarekit::vk
