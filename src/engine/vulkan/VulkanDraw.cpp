// SPDX-License-Identifier: Apache-2.0
// The Vulkan backend's flares: each used preset's sprites uploaded for the viewport's height,
// then one instanced draw per sprite over every light (light_flare.vert/.frag, compiled to
// SPIR-V), inside the engine's own dynamic rendering on the application's colour view.
#include <cstring>

#include "core/HalfFloat.h"
#include "engine/EngineInput.h"
#include "engine/vulkan/VulkanEngineImpl.h"
#include "flare/SpriteImages.h"

namespace flarekit::vk {

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
                writes[i] = descriptorWrite(set, binding, type, b, im);
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

}  // namespace flarekit::vk
