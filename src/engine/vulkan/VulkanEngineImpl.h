// SPDX-License-Identifier: Apache-2.0
// The state behind vk::VulkanEngine, shared by its three files: VulkanEngine.cpp (set-up,
// settings, frame slots), VulkanOcclusion.cpp (the batched occlusion pass and the small
// lights' sun maps) and VulkanDraw.cpp (the sprites and the instanced flares). Per-call
// numbers reach the GPU inside the command buffer (vkCmdUpdateBuffer), so a command buffer
// carries its own lights and matrices and nothing the host writes can race a frame in flight;
// the one thing made per call, a pass's descriptor set (it names the application's depth
// view), comes from the pool of the call's frame slot.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "engine/Engine.h"
#include "engine/SunMaps.h"
#include "engine/vulkan/VulkanEngine.h"
#include "engine/vulkan/VulkanParams.h"
#include "engine/vulkan/VulkanResources.h"

namespace flarekit::vk {

inline constexpr int kMaxFramesInFlight = 8;
//! Occlusion calls one frame may record (views x calls): each takes a set from its slot's pool.
inline constexpr std::uint32_t kSetsPerSlot = 32;
//! vkCmdUpdateBuffer's limit per command.
inline constexpr VkDeviceSize kUpdateChunk = 65536;
//! Floats per light in the lights buffer (light_view.glsl's Light).
inline constexpr VkDeviceSize kLightBytes = 16 * sizeof(float);

//! A global memory barrier: what `src` wrote (or read) before, made safe for `dst`.
void barrier(const Api& api, VkCommandBuffer cmd, VkPipelineStageFlags srcStage,
             VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

//! `bytes` into `buffer` at `offset` from the command buffer, in vkCmdUpdateBuffer's pieces.
void update(const Api& api, VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset,
            const void* bytes, VkDeviceSize size);

//! The readers of the engine's buffers (compute passes, the flare's vertex shader) are done
//! before a transfer rewrites them; the transfer's writes reach them after.
inline constexpr VkPipelineStageFlags kReaders =
    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT;

struct Binding {
    std::uint32_t binding;
    VkDescriptorType type;
    VkShaderStageFlags stages;
};

//! The checks both recorded passes make: the Vulkan frame's command buffer, the frame's
//! numbers and the lights.
Status checkCommon(const fk_vulkan_frame* vk, const fk_frame* frame, const fk_light* lights,
                   int count, int maxLights, int presets);
//! light_view.glsl's block for a frame (and whether its depth reaches past the viewport).
ViewParams viewParams(const fk_frame& f, bool pastViewport);

struct VulkanEngine::Impl {
    Device d;
    int maxLights = 0;
    int framesInFlight = 1;
    VkSampler nearest = VK_NULL_HANDLE, linear = VK_NULL_HANDLE;
    VkDescriptorSetLayout computeLayout = VK_NULL_HANDLE, drawLayout = VK_NULL_HANDLE;
    VkPipelineLayout computePipelineLayout = VK_NULL_HANDLE, drawPipelineLayout = VK_NULL_HANDLE;
    VkPipeline coverage[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};  //!< single-sample, multisampled
    VkDescriptorSetLayout sunMapLayout = VK_NULL_HANDLE;
    VkPipelineLayout sunMapPipelineLayout = VK_NULL_HANDLE;
    VkPipeline sunMap = VK_NULL_HANDLE;  //!< the sun maps' reduction (sunmap_coverage.comp)
    fk_vulkan_occluder_callback occluders = nullptr;
    void* occludersUser = nullptr;
    int tileBelow = engine::kDefaultTileBelow;
    engine::TileLayout tiling;
    Image atlas;  //!< FK_VULKAN_SUN_MAP_FORMAT, made with the first tile
    std::vector<int> tileOf;
    VkShaderModule flareVert = VK_NULL_HANDLE, flareFrag = VK_NULL_HANDLE;
    std::vector<std::pair<VkFormat, VkPipeline>> drawPipelines;  //!< one per colour format
    Buffer lights, state, tiles, params;
    Image coverageImage;
    bool coverageReady = false;  //!< the coverage image is in GENERAL

    struct Slot {
        VkDescriptorPool pool = VK_NULL_HANDLE;
        std::uint64_t frame = UINT64_MAX;
        std::vector<std::function<void()>> retired;  //!< freed when the slot comes round
    };
    std::vector<Slot> slots;
    int slot = 0;

    struct Sprite {
        Image image;
        Buffer element;  //!< ElementParams, host-visible, written once
        std::array<VkDescriptorSet, FK_MAX_VIEWS> sets{};
    };
    struct LoadedPreset {
        Preset preset;
        int height = 0;  //!< frame height its sprites were made for
        std::vector<Sprite> sprites;
        VkDescriptorPool pool = VK_NULL_HANDLE;
    };
    std::vector<LoadedPreset> presets;

    int samplesPerSide = engine::kDefaultSamplesPerSide;
    TemporalParams temporal;
    std::array<bool, FK_MAX_VIEWS> guardBand{};
    std::array<int, FK_MAX_VIEWS> lastCount{};
    std::vector<float> packed;

    ~Impl();
    Status createLayouts();
    Status createComputePipelines();
    Result<VkPipeline> drawPipeline(VkFormat format);
    void beginFrame(std::uint64_t frame);
    void retire(std::function<void()> f) {
        slots[std::size_t(slot)].retired.push_back(std::move(f));
    }
    void uploadLights(VkCommandBuffer cmd, const fk_light* lights, int count);
    Status ensureSprites(LoadedPreset& p, int presetId, int height, VkCommandBuffer cmd);
    Result<VkDescriptorSetLayout> makeLayout(std::initializer_list<Binding> bindings);
    //! The small lights' sun maps: the atlas drawn by the occluder callback, then reduced.
    //! `shared` holds the occlusion pass's descriptor writes (its buffers and images).
    Status measureSunMaps(VkCommandBuffer cmd, int view, const fk_frame& f,
                          const fk_light* lightArray, int count,
                          const VkWriteDescriptorSet* shared);
    Result<VkDescriptorPool> makePool(std::uint32_t sets, std::uint32_t ubos, std::uint32_t ssbos,
                                      std::uint32_t images, std::uint32_t samplers);
};

}  // namespace flarekit::vk
