// SPDX-License-Identifier: Apache-2.0
// The Vulkan backend's set-up (pipelines, buffers, the coverage image), its settings, frame
// slots and read-back; the passes are in VulkanOcclusion.cpp and VulkanDraw.cpp.
#include <algorithm>
#include <cstring>

#include "engine/EngineInput.h"
#include "engine/vulkan/VulkanEngineImpl.h"
#include "flarekit_exported_shaders.h"

namespace flarekit::vk {

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
