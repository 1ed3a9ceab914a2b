// SPDX-License-Identifier: Apache-2.0
// VulkanHost's depth images and its depth pass: a scene's opaque triangles drawn as a Vulkan
// application's depth pre-pass (vk_depth.vert), under any depth convention.
#include <cstring>

#include "engine/vulkan/VulkanHostImpl.h"
#include "flarekit_exported_shaders.h"

namespace flarekit::vk {

Result<DepthImage> VulkanHost::depthImage(int width, int height, int samples, VkFormat format) {
    const Device& d = m->d;
    DepthImage out;
    out.format = format;
    out.samples = samples;
    out.width = width;
    out.height = height;
    auto info = make<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {std::uint32_t(width), std::uint32_t(height), 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VkSampleCountFlagBits(samples);
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (Status s =
            check(d.api.vkCreateImage(d.device, &info, nullptr, &out.image), "vkCreateImage");
        !s)
        return s.error();
    VkMemoryRequirements r{};
    d.api.vkGetImageMemoryRequirements(d.device, out.image, &r);
    for (std::uint32_t i = 0; i < d.memory.memoryTypeCount && !out.memory; ++i) {
        if ((r.memoryTypeBits & (1u << i)) == 0 ||
            (d.memory.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) == 0)
            continue;
        auto alloc = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        alloc.allocationSize = r.size;
        alloc.memoryTypeIndex = i;
        if (d.api.vkAllocateMemory(d.device, &alloc, nullptr, &out.memory) != VK_SUCCESS)
            out.memory = VK_NULL_HANDLE;
    }
    if (!out.memory) {
        destroy(out);
        return internalError("no device memory for a depth image");
    }
    d.api.vkBindImageMemory(d.device, out.image, out.memory, 0);
    auto view = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    view.image = out.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    if (Status s = check(d.api.vkCreateImageView(d.device, &view, nullptr, &out.view),
                         "vkCreateImageView");
        !s) {
        destroy(out);
        return s.error();
    }
    return out;
}

void VulkanHost::destroy(DepthImage& depth) const {
    const Device& d = m->d;
    if (depth.view) d.api.vkDestroyImageView(d.device, depth.view, nullptr);
    if (depth.image) d.api.vkDestroyImage(d.device, depth.image, nullptr);
    if (depth.memory) d.api.vkFreeMemory(d.device, depth.memory, nullptr);
    depth = DepthImage{};
}

Result<VkPipeline> VulkanHost::Impl::depthPipeline(VkFormat format, int samples,
                                                   fk_depth_convention convention) {
    const std::uint64_t key =
        (std::uint64_t(format) << 8) | (std::uint64_t(samples) << 2) | std::uint64_t(convention);
    for (auto& [k, p] : depthPipelines)
        if (k == key) return p;
    auto module = d.makeShader(exported::vk_depth_vert_spv, exported::vk_depth_vert_spv_size);
    if (!module) return module.error();
    PipelineDesc desc;
    desc.vertex = *module;
    desc.vertexStride = 12;
    desc.samples = VkSampleCountFlagBits(samples);
    desc.depth = format;
    desc.depthCompare =
        convention == FK_DEPTH_REVERSED_Z ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
    desc.negativeOneToOne = convention == FK_DEPTH_MINUS_ONE_TO_ONE;
    desc.layout = depthLayout;
    auto made = d.makePipeline(desc);
    d.api.vkDestroyShaderModule(d.device, *module, nullptr);
    if (!made) return made.error();
    const VkPipeline pipeline = *made;
    depthPipelines.push_back({key, pipeline});
    return pipeline;
}

Status VulkanHost::drawDepth(const DepthImage& depth, const std::vector<float>& mesh,
                             const float viewProjection[16], fk_depth_convention convention) {
    const Device& d = m->d;
    if (convention == FK_DEPTH_MINUS_ONE_TO_ONE && !m->clipControl)
        return invalidInput("depth_convention: [-1, 1] depth needs VK_EXT_depth_clip_control");
    const bool reversedZ = convention == FK_DEPTH_REVERSED_Z;
    auto pipeline = m->depthPipeline(depth.format, depth.samples, convention);
    if (!pipeline) return pipeline.error();
    Buffer vertices;
    if (!mesh.empty()) {
        auto b = d.makeBuffer(VkDeviceSize(mesh.size() * sizeof(float)),
                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, true);
        if (!b) return b.error();
        vertices = *b;
        std::memcpy(vertices.mapped, mesh.data(), mesh.size() * sizeof(float));
    }
    const bool stencil = depth.format == VK_FORMAT_D24_UNORM_S8_UINT ||
                         depth.format == VK_FORMAT_D32_SFLOAT_S8_UINT ||
                         depth.format == VK_FORMAT_D16_UNORM_S8_UINT;
    const VkImageAspectFlags aspect =
        VK_IMAGE_ASPECT_DEPTH_BIT | (stencil ? VK_IMAGE_ASPECT_STENCIL_BIT : 0);
    Status s = submit([&](VkCommandBuffer cmd) {
        imageBarrier(d.api, cmd, depth.image, aspect, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                     VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                     VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                         VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
        auto attachment =
            make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
        attachment.imageView = depth.view;
        attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        attachment.clearValue.depthStencil = {reversedZ ? 0.f : 1.f, 0};
        auto rendering = make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
        rendering.renderArea = {{0, 0}, {std::uint32_t(depth.width), std::uint32_t(depth.height)}};
        rendering.layerCount = 1;
        rendering.pDepthAttachment = &attachment;
        d.api.vkCmdBeginRendering(cmd, &rendering);
        const VkViewport viewport{0, 0, float(depth.width), float(depth.height), 0, 1};
        d.api.vkCmdSetViewport(cmd, 0, 1, &viewport);
        d.api.vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
        d.api.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, *pipeline);
        m->h.vkCmdPushConstants(cmd, m->depthLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, 64,
                                viewProjection);
        if (vertices.buffer) {
            const VkDeviceSize offset = 0;
            m->h.vkCmdBindVertexBuffers(cmd, 0, 1, &vertices.buffer, &offset);
            d.api.vkCmdDraw(cmd, std::uint32_t(mesh.size() / 3), 1, 0, 0);
        }
        d.api.vkCmdEndRendering(cmd);
        imageBarrier(
            d.api, cmd, depth.image, aspect, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    });
    d.destroy(vertices);
    return s;
}

}  // namespace flarekit::vk
