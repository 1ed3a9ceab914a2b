// SPDX-License-Identifier: Apache-2.0
// The Vulkan backend's occlusion pass: every light measured on the application's depth in one
// dispatch, the small ones from sun maps the occluder callback draws (light_coverage.comp and
// sunmap_coverage.comp, compiled to SPIR-V).
#include <algorithm>
#include <cstring>

#include "engine/EngineInput.h"
#include "engine/TileChoice.h"
#include "engine/vulkan/VulkanEngineImpl.h"

namespace flarekit::vk {

namespace {

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

bool readableDepthLayout(VkImageLayout l) {
    return l == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL ||
           l == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL || l == VK_IMAGE_LAYOUT_GENERAL;
}

}  // namespace

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
    w[6] = descriptorWrite(set, 9, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr, &atlasInfo);
    w[7] = descriptorWrite(set, 11, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &tilingInfo, nullptr);
    a.vkUpdateDescriptorSets(d.device, 8, w, 0, nullptr);
    a.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, sunMap);
    a.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, sunMapPipelineLayout, 0, 1, &set,
                              0, nullptr);
    a.vkCmdDispatch(cmd, std::uint32_t(count), 1, 1);
    return Ok{};
}

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
        w[i] = descriptorWrite(set, binding, type, b, im);
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

}  // namespace flarekit::vk
