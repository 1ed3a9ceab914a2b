// SPDX-License-Identifier: Apache-2.0
// The Vulkan backend: set-up (pipelines, buffers, the coverage image) and the two recorded
// passes. Per-call numbers reach the GPU inside the command buffer (vkCmdUpdateBuffer), so a
// command buffer carries its own lights and matrices and nothing the host writes can race a
// frame in flight; the one thing made per call, the occlusion pass's descriptor set (it names
// the application's depth view), comes from the pool of the call's frame slot.
#include "engine/vulkan/VulkanEngine.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include "core/HalfFloat.h"
#include "engine/Engine.h"
#include "engine/EngineInput.h"
#include "engine/SunMaps.h"
#include "engine/TileChoice.h"
#include "engine/vulkan/VulkanParams.h"
#include "engine/vulkan/VulkanResources.h"
#include "flare/SpriteImages.h"
#include "flarekit_exported_shaders.h"

namespace flarekit::vk {

namespace {

constexpr int kMaxFramesInFlight = 8;
//! Occlusion calls one frame may record (views x calls): each takes a set from its slot's pool.
constexpr std::uint32_t kSetsPerSlot = 32;
//! vkCmdUpdateBuffer's limit per command.
constexpr VkDeviceSize kUpdateChunk = 65536;
//! Floats per light in the lights buffer (light_view.glsl's Light).
constexpr VkDeviceSize kLightBytes = 16 * sizeof(float);

//! Vulkan's standard sample locations (the specification's table, "Standard sample locations"),
//! x then y within the pixel, y down, for 1, 2, 4, 8 and 16 samples.
const float kStandard1[] = {0.5f, 0.5f};
const float kStandard2[] = {0.75f, 0.75f, 0.25f, 0.25f};
const float kStandard4[] = {0.375f, 0.125f, 0.875f, 0.375f, 0.125f, 0.625f, 0.625f, 0.875f};
const float kStandard8[] = {0.5625f, 0.3125f, 0.4375f, 0.6875f, 0.8125f, 0.5625f, 0.3125f, 0.1875f,
                            0.1875f, 0.8125f, 0.0625f, 0.4375f, 0.6875f, 0.9375f, 0.9375f, 0.0625f};
const float kStandard16[] = {0.5625f, 0.5625f, 0.4375f, 0.3125f, 0.3125f, 0.625f,  0.75f,   0.4375f,
                             0.1875f, 0.375f,  0.625f,  0.8125f, 0.8125f, 0.6875f, 0.6875f, 0.1875f,
                             0.375f,  0.875f,  0.5f,    0.0625f, 0.25f,   0.125f,  0.125f,  0.75f,
                             0.0f,    0.5f,    0.9375f, 0.25f,   0.875f,  0.9375f, 0.0625f, 0.0f};

const float* standardSamples(int n) {
    switch (n) {
        case 1:
            return kStandard1;
        case 2:
            return kStandard2;
        case 4:
            return kStandard4;
        case 8:
            return kStandard8;
        case 16:
            return kStandard16;
        default:
            return nullptr;
    }
}

//! A global memory barrier: what `src` wrote (or read) before, made safe for `dst`.
void barrier(const Api& api, VkCommandBuffer cmd, VkPipelineStageFlags srcStage,
             VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    auto b = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    api.vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

//! `bytes` into `buffer` at `offset` from the command buffer, in vkCmdUpdateBuffer's pieces.
void update(const Api& api, VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset,
            const void* bytes, VkDeviceSize size) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (VkDeviceSize at = 0; at < size; at += kUpdateChunk) {
        const VkDeviceSize n = std::min(kUpdateChunk, size - at);
        api.vkCmdUpdateBuffer(cmd, buffer, offset + at, (n + 3) / 4 * 4, p + at);
    }
}

//! The readers of the engine's buffers (compute passes, the flare's vertex shader) are done
//! before a transfer rewrites them; the transfer's writes reach them after.
constexpr VkPipelineStageFlags kReaders =
    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT;

bool readableDepthLayout(VkImageLayout l) {
    return l == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL || l == VK_IMAGE_LAYOUT_GENERAL;
}

struct Binding {
    std::uint32_t binding;
    VkDescriptorType type;
    VkShaderStageFlags stages;
};

}  // namespace

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

VulkanEngine::Impl::~Impl() {
    const Api& a = d.api;
    if (!d.device) return;
    for (Slot& s : slots) {
        for (auto& f : s.retired) f();
        if (s.pool) a.vkDestroyDescriptorPool(d.device, s.pool, d.allocator);
    }
    for (LoadedPreset& p : presets) {
        for (Sprite& s : p.sprites) d.destroy(s.image), d.destroy(s.element);
        if (p.pool) a.vkDestroyDescriptorPool(d.device, p.pool, d.allocator);
    }
    for (auto& [format, pipeline] : drawPipelines)
        a.vkDestroyPipeline(d.device, pipeline, d.allocator);
    for (VkPipeline p : {coverage[0], coverage[1], sunMap})
        if (p) a.vkDestroyPipeline(d.device, p, d.allocator);
    d.destroy(atlas);
    for (VkShaderModule m : {flareVert, flareFrag})
        if (m) a.vkDestroyShaderModule(d.device, m, d.allocator);
    for (VkPipelineLayout l : {computePipelineLayout, drawPipelineLayout, sunMapPipelineLayout})
        if (l) a.vkDestroyPipelineLayout(d.device, l, d.allocator);
    for (VkDescriptorSetLayout l : {computeLayout, drawLayout, sunMapLayout})
        if (l) a.vkDestroyDescriptorSetLayout(d.device, l, d.allocator);
    for (VkSampler s : {nearest, linear})
        if (s) a.vkDestroySampler(d.device, s, d.allocator);
    for (Buffer* b : {&lights, &state, &tiles, &params}) d.destroy(*b);
    d.destroy(coverageImage);
}

Result<VkDescriptorSetLayout> VulkanEngine::Impl::makeLayout(
    std::initializer_list<Binding> bindings) {
    std::vector<VkDescriptorSetLayoutBinding> list;
    for (const Binding& b : bindings) list.push_back({b.binding, b.type, 1, b.stages, nullptr});
    auto info =
        make<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    info.bindingCount = std::uint32_t(list.size());
    info.pBindings = list.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    if (Status s = check(d.api.vkCreateDescriptorSetLayout(d.device, &info, d.allocator, &layout),
                         "vkCreateDescriptorSetLayout");
        !s)
        return s.error();
    return layout;
}

Result<VkDescriptorPool> VulkanEngine::Impl::makePool(std::uint32_t sets, std::uint32_t ubos,
                                                      std::uint32_t ssbos, std::uint32_t images,
                                                      std::uint32_t samplers) {
    std::vector<VkDescriptorPoolSize> sizes;
    if (ubos) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, ubos * sets});
    if (ssbos) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ssbos * sets});
    if (images) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, images * sets});
    if (samplers) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, samplers * sets});
    auto info = make<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    info.maxSets = sets;
    info.poolSizeCount = std::uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (Status s = check(d.api.vkCreateDescriptorPool(d.device, &info, d.allocator, &pool),
                         "vkCreateDescriptorPool");
        !s)
        return s.error();
    return pool;
}

Status VulkanEngine::Impl::createLayouts() {
    constexpr VkShaderStageFlags C = VK_SHADER_STAGE_COMPUTE_BIT, V = VK_SHADER_STAGE_VERTEX_BIT,
                                 F = VK_SHADER_STAGE_FRAGMENT_BIT;
    constexpr VkDescriptorType UBO = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                               SSBO = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                               IMAGE = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                               SAMPLED = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    // The bindings backend.glsl's BINDING(gl, vk) and UNIFORMS_BEGIN give under VULKAN.
    auto compute = makeLayout({{0, UBO, C},
                               {1, SSBO, C},
                               {2, SSBO, C},
                               {3, SSBO, C},
                               {4, IMAGE, C},
                               {5, SAMPLED, C},
                               {6, SAMPLED, C},
                               {10, UBO, C},
                               {11, UBO, C}});
    if (!compute) return compute.error();
    computeLayout = *compute;
    auto draw = makeLayout(
        {{0, UBO, V}, {1, SSBO, V}, {7, SAMPLED, V}, {8, SAMPLED, F}, {12, UBO, V}, {13, UBO, V}});
    if (!draw) return draw.error();
    drawLayout = *draw;
    auto sunMaps = makeLayout({{0, UBO, C},
                               {1, SSBO, C},
                               {2, SSBO, C},
                               {3, SSBO, C},
                               {4, IMAGE, C},
                               {9, SAMPLED, C},
                               {10, UBO, C},
                               {11, UBO, C}});
    if (!sunMaps) return sunMaps.error();
    sunMapLayout = *sunMaps;
    for (auto [set, out] : {std::pair{computeLayout, &computePipelineLayout},
                            std::pair{drawLayout, &drawPipelineLayout},
                            std::pair{sunMapLayout, &sunMapPipelineLayout}}) {
        auto info = make<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
        info.setLayoutCount = 1;
        info.pSetLayouts = &set;
        if (Status s = check(d.api.vkCreatePipelineLayout(d.device, &info, d.allocator, out),
                             "vkCreatePipelineLayout");
            !s)
            return s;
    }
    return Ok{};
}

Status VulkanEngine::Impl::createComputePipelines() {
    namespace x = exported;
    const std::pair<const unsigned char*, std::size_t> code[3] = {
        {x::vk_coverage_comp_spv, x::vk_coverage_comp_spv_size},
        {x::vk_coverage_ms_comp_spv, x::vk_coverage_ms_comp_spv_size},
        {x::vk_sunmap_comp_spv, x::vk_sunmap_comp_spv_size}};
    VkPipeline* out[3] = {&coverage[0], &coverage[1], &sunMap};
    for (int i = 0; i < 3; ++i) {
        auto module = d.makeShader(code[i].first, code[i].second);
        if (!module) return module.error();
        auto info =
            make<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
        info.stage = make<VkPipelineShaderStageCreateInfo>(
            VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
        info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        info.stage.module = *module;
        info.stage.pName = "main";
        info.layout = i < 2 ? computePipelineLayout : sunMapPipelineLayout;
        const VkResult r =
            d.api.vkCreateComputePipelines(d.device, VK_NULL_HANDLE, 1, &info, d.allocator, out[i]);
        d.api.vkDestroyShaderModule(d.device, *module, d.allocator);
        if (Status s = check(r, "vkCreateComputePipelines"); !s) return s;
    }
    auto vert = d.makeShader(x::vk_flare_vert_spv, x::vk_flare_vert_spv_size);
    if (!vert) return vert.error();
    flareVert = *vert;
    auto frag = d.makeShader(x::vk_flare_frag_spv, x::vk_flare_frag_spv_size);
    if (!frag) return frag.error();
    flareFrag = *frag;
    return Ok{};
}

Result<VkPipeline> VulkanEngine::Impl::drawPipeline(VkFormat format) {
    for (auto& [f, p] : drawPipelines)
        if (f == format) return p;
    PipelineDesc desc;
    desc.vertex = flareVert;
    desc.fragment = flareFrag;
    desc.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;  // four vertices a quad, instanced
    desc.blend = PipelineDesc::Blend::Add;
    desc.color = format;
    desc.layout = drawPipelineLayout;
    auto pipeline = d.makePipeline(desc);
    if (!pipeline) return pipeline.error();
    drawPipelines.push_back({format, *pipeline});
    return *pipeline;
}

void VulkanEngine::Impl::beginFrame(std::uint64_t frame) {
    slot = int(frame % std::uint64_t(framesInFlight));
    Slot& s = slots[std::size_t(slot)];
    if (s.frame == frame) return;
    // The application waited for frame - framesInFlight, the slot's last: its sets and what it
    // retired are free.
    for (auto& f : s.retired) f();
    s.retired.clear();
    d.api.vkResetDescriptorPool(d.device, s.pool, 0);
    s.frame = frame;
}

void VulkanEngine::Impl::uploadLights(VkCommandBuffer cmd, const fk_light* lightArray, int count) {
    engine::packLights(lightArray, count, packed);
    update(d.api, cmd, lights.buffer, 0, packed.data(),
           VkDeviceSize(packed.size() * sizeof(float)));
}

Status VulkanEngine::Impl::ensureSprites(LoadedPreset& p, int presetId, int height,
                                         VkCommandBuffer cmd) {
    if (p.height == height) return Ok{};
    // The old sprites may be drawn by frames in flight: freed when this slot comes round.
    if (!p.sprites.empty() || p.pool) {
        std::vector<Sprite> old = std::move(p.sprites);
        VkDescriptorPool oldPool = p.pool;
        retire([this, old, oldPool]() mutable {
            for (Sprite& s : old) d.destroy(s.image), d.destroy(s.element);
            if (oldPool) d.api.vkDestroyDescriptorPool(d.device, oldPool, d.allocator);
        });
        p.sprites.clear();
        p.pool = VK_NULL_HANDLE;
    }
    p.height = height;
    std::vector<SpriteImage> images = renderSpriteImages(p.preset, height);
    if (images.empty()) return Ok{};
    auto pool = makePool(std::uint32_t(images.size()) * FK_MAX_VIEWS, 3, 1, 0, 2);
    if (!pool) return pool.error();
    p.pool = *pool;
    for (const SpriteImage& s : images) {
        Sprite sprite;
        const int w = s.image.width(), h = s.image.height();
        auto image = d.makeImage(VK_FORMAT_R16G16B16A16_SFLOAT, std::uint32_t(w), std::uint32_t(h),
                                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
        if (!image) return image.error();
        sprite.image = *image;
        const VkDeviceSize bytes = VkDeviceSize(w) * VkDeviceSize(h) * 4 * 2;
        auto staging = d.makeBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
        if (!staging) {
            d.destroy(sprite.image);
            return staging.error();
        }
        floatsToHalf(s.image.data(), std::size_t(w) * std::size_t(h), 4,
                     static_cast<std::uint16_t*>(staging->mapped));
        imageBarrier(d.api, cmd, sprite.image.image, VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {std::uint32_t(w), std::uint32_t(h), 1};
        d.api.vkCmdCopyBufferToImage(cmd, staging->buffer, sprite.image.image,
                                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        imageBarrier(d.api, cmd, sprite.image.image, VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
        Buffer used = *staging;
        retire([this, used]() mutable { d.destroy(used); });
        auto element =
            d.makeBuffer(sizeof(ElementParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        if (!element) {
            d.destroy(sprite.image);
            return element.error();
        }
        sprite.element = *element;
        const ElementParams e{{s.halfW, s.halfH}, presetId, s.t, s.edgeStreak ? 1u : 0u, s.reach};
        std::memcpy(sprite.element.mapped, &e, sizeof e);
        for (int v = 0; v < FK_MAX_VIEWS; ++v) {
            auto alloc =
                make<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
            alloc.descriptorPool = p.pool;
            alloc.descriptorSetCount = 1;
            alloc.pSetLayouts = &drawLayout;
            VkDescriptorSet& set = sprite.sets[std::size_t(v)];
            if (Status st = check(d.api.vkAllocateDescriptorSets(d.device, &alloc, &set),
                                  "vkAllocateDescriptorSets");
                !st) {
                d.destroy(sprite.image), d.destroy(sprite.element);
                return st;
            }
            const VkDeviceSize at = VkDeviceSize(v) * kParamsPerView;
            const VkDescriptorBufferInfo view{params.buffer, at + kViewParamsAt,
                                              sizeof(ViewParams)};
            const VkDescriptorBufferInfo flare{params.buffer, at + kFlareParamsAt,
                                               sizeof(FlareParams)};
            const VkDescriptorBufferInfo lightInfo{lights.buffer, 0, VK_WHOLE_SIZE};
            const VkDescriptorBufferInfo elementInfo{sprite.element.buffer, 0,
                                                     sizeof(ElementParams)};
            const VkDescriptorImageInfo coverageInfo{nearest, coverageImage.view,
                                                     VK_IMAGE_LAYOUT_GENERAL};
            const VkDescriptorImageInfo spriteInfo{linear, sprite.image.view,
                                                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            VkWriteDescriptorSet writes[6];
            const auto write = [&](int i, std::uint32_t binding, VkDescriptorType type,
                                   const VkDescriptorBufferInfo* b,
                                   const VkDescriptorImageInfo* im) {
                writes[i] = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
                writes[i].dstSet = set;
                writes[i].dstBinding = binding;
                writes[i].descriptorCount = 1;
                writes[i].descriptorType = type;
                writes[i].pBufferInfo = b;
                writes[i].pImageInfo = im;
            };
            write(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &view, nullptr);
            write(1, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &lightInfo, nullptr);
            write(2, 7, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &coverageInfo);
            write(3, 8, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &spriteInfo);
            write(4, 12, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &flare, nullptr);
            write(5, 13, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &elementInfo, nullptr);
            d.api.vkUpdateDescriptorSets(d.device, 6, writes, 0, nullptr);
        }
        p.sprites.push_back(std::move(sprite));
    }
    return Ok{};
}

Status VulkanEngine::Impl::measureSunMaps(VkCommandBuffer cmd, int view, const fk_frame& f,
                                          const fk_light* lightArray, int count,
                                          const VkWriteDescriptorSet* shared) {
    const Api& a = d.api;
    const int side = tiling.tileSize * tiling.tilesPerRow;
    if (!atlas.image) {
        auto made = d.makeImage(FK_VULKAN_SUN_MAP_FORMAT, std::uint32_t(side), std::uint32_t(side),
                                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
        if (!made) return made.error();
        atlas = *made;
    }
    auto alloc = make<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    alloc.descriptorPool = slots[std::size_t(slot)].pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &sunMapLayout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (a.vkAllocateDescriptorSets(d.device, &alloc, &set) != VK_SUCCESS)
        return invalidInput("vulkan frame.frame_index: too many occlusion calls in one frame");
    // The previous reduction's reads of the atlas end before it is drawn again.
    imageBarrier(a, cmd, atlas.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    auto target = make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    target.imageView = atlas.view;
    target.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    target.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    target.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    target.clearValue.color = {{1.f, 1.f, 1.f, 1.f}};  // white: nothing hides the light
    auto rendering = make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    rendering.renderArea = {{0, 0}, {std::uint32_t(side), std::uint32_t(side)}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &target;
    a.vkCmdBeginRendering(cmd, &rendering);
    for (int i = 0; i < count; ++i) {
        const int tile = tileOf[std::size_t(i)];
        float vp[16];
        if (tile < 0 || !engine::sunMapCamera(f, lightArray[i], vp)) continue;
        const int x = (tile % tiling.tilesPerRow) * tiling.tileSize,
                  y = (tile / tiling.tilesPerRow) * tiling.tileSize;
        const VkViewport viewport{
            float(x), float(y), float(tiling.tileSize), float(tiling.tileSize), 0.f, 1.f};
        const VkRect2D scissor{{x, y},
                               {std::uint32_t(tiling.tileSize), std::uint32_t(tiling.tileSize)}};
        a.vkCmdSetViewport(cmd, 0, 1, &viewport);
        a.vkCmdSetScissor(cmd, 0, 1, &scissor);
        occluders(occludersUser, cmd, view, i, vp);
    }
    a.vkCmdEndRendering(cmd);
    imageBarrier(a, cmd, atlas.image, VK_IMAGE_ASPECT_COLOR_BIT,
                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                 VK_ACCESS_SHADER_READ_BIT);
    // The occlusion pass's buffers and coverage image (writes 0-4 and 7: bindings 0-4, 10),
    // the atlas at 9 and the tile layout at 11.
    const VkDescriptorImageInfo atlasInfo{nearest, atlas.view,
                                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorBufferInfo tilingInfo{
        params.buffer, VkDeviceSize(view) * kParamsPerView + kSunMapParamsAt, sizeof(SunMapParams)};
    VkWriteDescriptorSet w[8];
    for (int i = 0; i < 5; ++i) w[i] = shared[i], w[i].dstSet = set;
    w[5] = shared[7], w[5].dstSet = set;
    w[6] = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w[6].dstSet = set, w[6].dstBinding = 9, w[6].descriptorCount = 1;
    w[6].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, w[6].pImageInfo = &atlasInfo;
    w[7] = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w[7].dstSet = set, w[7].dstBinding = 11, w[7].descriptorCount = 1;
    w[7].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, w[7].pBufferInfo = &tilingInfo;
    a.vkUpdateDescriptorSets(d.device, 8, w, 0, nullptr);
    a.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, sunMap);
    a.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, sunMapPipelineLayout, 0, 1, &set,
                              0, nullptr);
    a.vkCmdDispatch(cmd, std::uint32_t(count), 1, 1);
    return Ok{};
}

VulkanEngine::VulkanEngine(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
VulkanEngine::~VulkanEngine() = default;

Result<std::unique_ptr<VulkanEngine>> VulkanEngine::create(const fk_vulkan_device& dev,
                                                           int maxLights) {
    if (maxLights < 1 || maxLights > FK_MAX_LIGHTS) {
        return invalidInput("max_lights: expected 1.." + std::to_string(FK_MAX_LIGHTS) + ", got " +
                            std::to_string(maxLights));
    }
    if (!dev.instance || !dev.physical_device || !dev.device) {
        return invalidInput(
            "device: expected the application's instance, physical device and device, got a "
            "null handle");
    }
    if (dev.frames_in_flight < 1 || dev.frames_in_flight > kMaxFramesInFlight) {
        return invalidInput("frames_in_flight: expected 1.." + std::to_string(kMaxFramesInFlight) +
                            ", got " + std::to_string(dev.frames_in_flight));
    }
    auto api = loadApi(dev.get_instance_proc_addr, dev.instance, dev.device);
    if (!api) return api.error();
    auto m = std::make_unique<Impl>();
    Device& d = m->d;
    d.api = *api;
    d.instance = dev.instance;
    d.physical = dev.physical_device;
    d.device = dev.device;
    d.allocator = dev.allocator;
    d.api.vkGetPhysicalDeviceMemoryProperties(d.physical, &d.memory);
    d.api.vkGetPhysicalDeviceProperties(d.physical, &d.properties);
    if (d.properties.limits.maxComputeWorkGroupCount[0] < std::uint32_t(maxLights)) {
        return invalidInput("max_lights: the device dispatches at most " +
                            std::to_string(d.properties.limits.maxComputeWorkGroupCount[0]) +
                            " work groups, one per light");
    }
    m->maxLights = maxLights;
    m->framesInFlight = dev.frames_in_flight;
    if (Status s = m->createLayouts(); !s) return s.error();
    if (Status s = m->createComputePipelines(); !s) return s.error();
    for (auto [filter, out] :
         {std::pair{VK_FILTER_NEAREST, &m->nearest}, std::pair{VK_FILTER_LINEAR, &m->linear}}) {
        auto sampler = d.makeSampler(filter);
        if (!sampler) return sampler.error();
        *out = *sampler;
    }
    constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    constexpr VkBufferUsageFlags kUpdated = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    auto lights = d.makeBuffer(VkDeviceSize(maxLights) * kLightBytes, kStorage | kUpdated, false);
    if (!lights) return lights.error();
    m->lights = *lights;
    // The state is read by the host (fk_engine_read_view): host-visible, zero to start.
    const VkDeviceSize stateBytes = VkDeviceSize(maxLights) * FK_MAX_VIEWS * 4 * sizeof(float);
    auto state = d.makeBuffer(stateBytes, kStorage, true);
    if (!state) return state.error();
    m->state = *state;
    std::memset(m->state.mapped, 0, stateBytes);
    // Each call's tiles (-1: on the depth) travel in its command buffer.
    const VkDeviceSize tileBytes = VkDeviceSize(maxLights) * FK_MAX_VIEWS * sizeof(std::int32_t);
    auto tiles = d.makeBuffer(tileBytes, kStorage | kUpdated, false);
    if (!tiles) return tiles.error();
    m->tiles = *tiles;
    m->tiling = engine::tileLayout(maxLights);
    auto params = d.makeBuffer(kParamsPerView * FK_MAX_VIEWS,
                               VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | kUpdated, false);
    if (!params) return params.error();
    m->params = *params;
    auto coverage = d.makeImage(VK_FORMAT_R32_SFLOAT, std::uint32_t(maxLights), FK_MAX_VIEWS,
                                VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
    if (!coverage) return coverage.error();
    m->coverageImage = *coverage;
    m->slots.resize(std::size_t(m->framesInFlight));
    for (Impl::Slot& s : m->slots) {
        auto pool = m->makePool(kSetsPerSlot, 3, 3, 1, 2);
        if (!pool) return pool.error();
        s.pool = *pool;
    }
    return std::unique_ptr<VulkanEngine>(new VulkanEngine(std::move(m)));
}

Result<int> VulkanEngine::addPreset(Preset preset) {
    m->presets.push_back({std::move(preset), 0, {}, VK_NULL_HANDLE});
    return int(m->presets.size()) - 1;
}

Status VulkanEngine::setSamples(int perSide) {
    if (Status s = engine::checkSamplesPerSide(perSide); !s) return s;
    m->samplesPerSide = perSide;
    return Ok{};
}

Status VulkanEngine::setTemporal(float attackSeconds, float releaseSeconds, float guardBand) {
    return engine::setTemporalParams(m->temporal, attackSeconds, releaseSeconds, guardBand);
}

Status VulkanEngine::setGuardBand(int view, bool enabled) {
    if (Status s = engine::checkView(view); !s) return s;
    m->guardBand[std::size_t(view)] = enabled;
    return Ok{};
}

Status VulkanEngine::setTileThreshold(int depthSamples) {
    if (depthSamples < 0 || depthSamples > engine::kMaxTileBelow) {
        return invalidInput("tile-below: expected 0.." + std::to_string(engine::kMaxTileBelow) +
                            " depth samples, got " + std::to_string(depthSamples));
    }
    m->tileBelow = depthSamples;
    return Ok{};
}

Status VulkanEngine::setOccluderCallback(fk_vulkan_occluder_callback callback, void* user) {
    m->occluders = callback;
    m->occludersUser = user;
    return Ok{};
}

Status VulkanEngine::reset() {
    std::memset(m->state.mapped, 0, m->state.size);
    m->lastCount.fill(0);
    return Ok{};
}

VkImageView VulkanEngine::coverageView() const {
    return m->coverageImage.view;
}

namespace {
Status checkCommon(const fk_vulkan_frame* vk, const fk_frame* frame, const fk_light* lights,
                   int count, int maxLights, int presets) {
    if (!vk) return invalidInput("vulkan frame: expected an fk_vulkan_frame, got NULL");
    if (!vk->command_buffer)
        return invalidInput("vulkan frame.command_buffer: expected a recording command buffer");
    if (Status s = engine::checkFrameNumbers(frame, "frame"); !s) return s;
    return engine::checkLights(lights, count, maxLights, presets);
}

ViewParams viewParams(const fk_frame& f, bool pastViewport) {
    ViewParams p{};
    std::memcpy(p.viewMatrix, f.view, sizeof p.viewMatrix);
    std::memcpy(p.projectionMatrix, f.projection, sizeof p.projectionMatrix);
    std::memcpy(p.viewport, f.viewport, sizeof p.viewport);
    p.depthTextureSize[0] = float(f.width);
    p.depthTextureSize[1] = float(f.height);
    p.depthConvention = std::int32_t(f.depth_convention);
    p.depthPastViewport = pastViewport ? 1u : 0u;
    return p;
}
}  // namespace

Status VulkanEngine::recordOcclusion(int view, const fk_vulkan_frame* vk, const fk_frame* frame,
                                     const fk_light* lights, int count) {
    if (Status s = engine::checkView(view); !s) return s;
    if (Status s = checkCommon(vk, frame, lights, count, m->maxLights, int(m->presets.size())); !s)
        return s;
    if (!vk->depth_view)
        return invalidInput("vulkan frame.depth_view: expected the depth image's view");
    if (!readableDepthLayout(vk->depth_layout)) {
        return invalidInput(
            "vulkan frame.depth_layout: expected DEPTH_STENCIL_READ_ONLY_OPTIMAL, "
            "DEPTH_READ_ONLY_OPTIMAL, SHADER_READ_ONLY_OPTIMAL or GENERAL, got " +
            std::to_string(int(vk->depth_layout)));
    }
    const int samples = int(vk->depth_samples);
    if (!standardSamples(samples)) {
        return invalidInput("vulkan frame.depth_samples: expected 1, 2, 4, 8 or 16, got " +
                            std::to_string(samples));
    }
    if (vk->transmittance_view &&
        vk->transmittance_layout != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL &&
        vk->transmittance_layout != VK_IMAGE_LAYOUT_GENERAL) {
        return invalidInput(
            "vulkan frame.transmittance_layout: expected SHADER_READ_ONLY_OPTIMAL or GENERAL");
    }
    m->lastCount[std::size_t(view)] = count;
    if (count == 0) return Ok{};
    const Api& a = m->d.api;
    const VkCommandBuffer cmd = vk->command_buffer;
    m->beginFrame(vk->frame_index);
    auto alloc = make<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    alloc.descriptorPool = m->slots[std::size_t(m->slot)].pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &m->computeLayout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (a.vkAllocateDescriptorSets(m->d.device, &alloc, &set) != VK_SUCCESS) {
        return invalidInput("vulkan frame.frame_index: more than " + std::to_string(kSetsPerSlot) +
                            " occlusion calls in frame " + std::to_string(vk->frame_index) +
                            " (is frame_index counting frames?)");
    }
    if (!m->coverageReady) {
        imageBarrier(a, cmd, m->coverageImage.image, VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_ACCESS_SHADER_WRITE_BIT);
        m->coverageReady = true;
    }
    // Earlier passes' reads of the lights and parameters end before they are rewritten.
    barrier(a, cmd, kReaders, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    m->uploadLights(cmd, lights, count);
    const fk_frame& f = *frame;
    const VkDeviceSize at = VkDeviceSize(view) * kParamsPerView;
    const ViewParams vp = viewParams(f, m->guardBand[std::size_t(view)]);
    const StateParams sp{view, view * m->maxLights,
                         float(smoothingStep(f.dt_seconds, m->temporal.attackSeconds)),
                         float(smoothingStep(f.dt_seconds, m->temporal.releaseSeconds))};
    CoverageParams cp{};
    cp.perSide = m->samplesPerSide;
    cp.samplesPerPixel = samples;
    cp.hasTransmittance = vk->transmittance_view ? 1u : 0u;
    cp.sampleCount = samples;
    const float* positions = standardSamples(samples);
    for (int i = 0; i < samples; ++i)
        cp.samplePositions[i][0] = positions[2 * i],
        cp.samplePositions[i][1] = positions[2 * i + 1];
    update(a, cmd, m->params.buffer, at + kViewParamsAt, &vp, sizeof vp);
    update(a, cmd, m->params.buffer, at + kStateParamsAt, &sp, sizeof sp);
    update(a, cmd, m->params.buffer, at + kCoverageParamsAt, &cp, sizeof cp);
    // Which lights sun maps measure (none without an occluder callback).
    const int tiled = engine::chooseTiles(f, samples, lights, count, false,
                                          m->occluders ? m->tileBelow : 0, m->tileOf);
    update(a, cmd, m->tiles.buffer,
           VkDeviceSize(view) * VkDeviceSize(m->maxLights) * sizeof(std::int32_t), m->tileOf.data(),
           VkDeviceSize(count) * sizeof(std::int32_t));
    const SunMapParams tp{m->tiling.tileSize, m->tiling.tilesPerRow};
    update(a, cmd, m->params.buffer, at + kSunMapParamsAt, &tp, sizeof tp);
    // The uploads, and the previous pass's state writes, before this pass reads them.
    barrier(a, cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
            VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
            VK_ACCESS_UNIFORM_READ_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);

    const VkDescriptorBufferInfo viewInfo{m->params.buffer, at + kViewParamsAt, sizeof(ViewParams)};
    const VkDescriptorBufferInfo stateParams{m->params.buffer, at + kStateParamsAt,
                                             sizeof(StateParams)};
    const VkDescriptorBufferInfo coverageParams{m->params.buffer, at + kCoverageParamsAt,
                                                sizeof(CoverageParams)};
    const VkDescriptorBufferInfo lightInfo{m->lights.buffer, 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo stateInfo{m->state.buffer, 0, VK_WHOLE_SIZE};
    const VkDescriptorBufferInfo tileInfo{m->tiles.buffer, 0, VK_WHOLE_SIZE};
    const VkDescriptorImageInfo coverageImage{VK_NULL_HANDLE, m->coverageImage.view,
                                              VK_IMAGE_LAYOUT_GENERAL};
    const VkDescriptorImageInfo depth{m->nearest, vk->depth_view, vk->depth_layout};
    // Without a transmittance image the shader never samples binding 6; the coverage image
    // (already in GENERAL) fills it.
    const VkDescriptorImageInfo kept =
        vk->transmittance_view
            ? VkDescriptorImageInfo{m->linear, vk->transmittance_view, vk->transmittance_layout}
            : VkDescriptorImageInfo{m->linear, m->coverageImage.view, VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet w[9];
    const auto write = [&](int i, std::uint32_t binding, VkDescriptorType type,
                           const VkDescriptorBufferInfo* b, const VkDescriptorImageInfo* im) {
        w[i] = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        w[i].dstSet = set;
        w[i].dstBinding = binding;
        w[i].descriptorCount = 1;
        w[i].descriptorType = type;
        w[i].pBufferInfo = b;
        w[i].pImageInfo = im;
    };
    write(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &viewInfo, nullptr);
    write(1, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &lightInfo, nullptr);
    write(2, 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &stateInfo, nullptr);
    write(3, 3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &tileInfo, nullptr);
    write(4, 4, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, nullptr, &coverageImage);
    write(5, 5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &depth);
    write(6, 6, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &kept);
    write(7, 10, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &stateParams, nullptr);
    write(8, 11, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &coverageParams, nullptr);
    a.vkUpdateDescriptorSets(m->d.device, 9, w, 0, nullptr);
    if (tiled > 0) {
        if (Status s = m->measureSunMaps(cmd, view, f, lights, count, w); !s) return s;
    }
    a.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m->coverage[samples > 1 ? 1 : 0]);
    a.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m->computePipelineLayout, 0, 1,
                              &set, 0, nullptr);
    a.vkCmdDispatch(cmd, std::uint32_t(count), 1, 1);
    // The coverage reaches the flare draw, the next frame's pass and the host.
    barrier(a, cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_HOST_READ_BIT);
    return Ok{};
}

Status VulkanEngine::recordDraw(int view, const fk_vulkan_frame* vk, const fk_frame* frame,
                                const fk_light* lights, int count) {
    if (Status s = engine::checkView(view); !s) return s;
    if (Status s = checkCommon(vk, frame, lights, count, m->maxLights, int(m->presets.size())); !s)
        return s;
    if (!vk->color_view)
        return invalidInput("vulkan frame.color_view: expected the colour image's view");
    if (vk->color_layout != VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL &&
        vk->color_layout != VK_IMAGE_LAYOUT_GENERAL) {
        return invalidInput(
            "vulkan frame.color_layout: expected COLOR_ATTACHMENT_OPTIMAL or GENERAL");
    }
    VkFormatProperties props{};
    m->d.api.vkGetPhysicalDeviceFormatProperties(m->d.physical, vk->color_format, &props);
    constexpr VkFormatFeatureFlags kBlendable =
        VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT;
    if ((props.optimalTilingFeatures & kBlendable) != kBlendable) {
        return invalidInput(
            "vulkan frame.color_format: expected a format the device blends "
            "into as a colour attachment, got " +
            std::to_string(int(vk->color_format)));
    }
    if (count == 0) return Ok{};
    const Api& a = m->d.api;
    const VkCommandBuffer cmd = vk->command_buffer;
    m->beginFrame(vk->frame_index);
    auto pipeline = m->drawPipeline(vk->color_format);
    if (!pipeline) return pipeline.error();
    const int height = frame->viewport[3];
    std::vector<char> used(m->presets.size(), 0);
    for (int i = 0; i < count; ++i)
        if (lights[i].preset >= 0) used[std::size_t(lights[i].preset)] = 1;
    for (std::size_t p = 0; p < m->presets.size(); ++p)
        if (used[p])
            if (Status s = m->ensureSprites(m->presets[p], int(p), height, cmd); !s) return s;
    barrier(a, cmd, kReaders, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    m->uploadLights(cmd, lights, count);
    const VkDeviceSize at = VkDeviceSize(view) * kParamsPerView;
    const ViewParams vp = viewParams(*frame, false);
    const FlareParams fp{0, 1u, view, float(m->temporal.guardBand), float(kReferenceFlux)};
    update(a, cmd, m->params.buffer, at + kViewParamsAt, &vp, sizeof vp);
    update(a, cmd, m->params.buffer, at + kFlareParamsAt, &fp, sizeof fp);
    barrier(a, cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_VERTEX_SHADER_BIT,
            VK_ACCESS_UNIFORM_READ_BIT | VK_ACCESS_SHADER_READ_BIT);

    auto color = make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    color.imageView = vk->color_view;
    color.imageLayout = vk->color_layout;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    auto rendering = make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    const int* v = frame->viewport;
    rendering.renderArea = {{v[0], v[1]}, {std::uint32_t(v[2]), std::uint32_t(v[3])}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    a.vkCmdBeginRendering(cmd, &rendering);
    const VkViewport viewport{float(v[0]), float(v[1]), float(v[2]), float(v[3]), 0.f, 1.f};
    a.vkCmdSetViewport(cmd, 0, 1, &viewport);
    a.vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
    a.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, *pipeline);
    for (std::size_t p = 0; p < m->presets.size(); ++p) {
        if (!used[p]) continue;
        for (const Impl::Sprite& s : m->presets[p].sprites) {
            a.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m->drawPipelineLayout,
                                      0, 1, &s.sets[std::size_t(view)], 0, nullptr);
            a.vkCmdDraw(cmd, 4, std::uint32_t(count), 0, 0);
        }
    }
    a.vkCmdEndRendering(cmd);
    return Ok{};
}

Result<int> VulkanEngine::readView(int view, float* coverage, float* inFrame, float* filtered,
                                   int count) {
    if (Status s = engine::checkView(view); !s) return s.error();
    if (count < 0) return invalidInput("count: expected >= 0, got " + std::to_string(count));
    if (count > 0 && !coverage && !inFrame && !filtered)
        return invalidInput("out: expected an array of count floats, got NULL");
    const int n = std::min(count, m->lastCount[std::size_t(view)]);
    const auto* state = static_cast<const float*>(m->state.mapped) +
                        std::size_t(view) * std::size_t(m->maxLights) * 4;
    for (int i = 0; i < n; ++i) {
        const float* s = state + std::size_t(i) * 4;
        if (coverage) coverage[i] = s[0];
        if (filtered) filtered[i] = s[1];
        if (inFrame) inFrame[i] = s[2];
    }
    return n;
}

}  // namespace flarekit::vk
