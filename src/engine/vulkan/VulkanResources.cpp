// SPDX-License-Identifier: Apache-2.0
#include "engine/vulkan/VulkanResources.h"

#include <cstring>

namespace flarekit::vk {

Status check(VkResult result, const char* call) {
    if (result == VK_SUCCESS) return Ok{};
    return internalError(std::string(call) + " failed: " + resultName(result));
}

void imageBarrier(const Api& api, VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                  VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    auto b = make<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    api.vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

Result<VkDeviceMemory> Device::allocate(const VkMemoryRequirements& r,
                                        VkMemoryPropertyFlags wanted) const {
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        if ((r.memoryTypeBits & (1u << i)) == 0) continue;
        if ((memory.memoryTypes[i].propertyFlags & wanted) != wanted) continue;
        auto info = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        info.allocationSize = r.size;
        info.memoryTypeIndex = i;
        VkDeviceMemory m = VK_NULL_HANDLE;
        if (Status s =
                check(api.vkAllocateMemory(device, &info, allocator, &m), "vkAllocateMemory");
            !s)
            return s.error();
        return m;
    }
    return internalError("the device has no memory type with the properties the engine needs");
}

Result<Buffer> Device::makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage,
                                  bool hostVisible) const {
    Buffer b;
    b.size = size;
    auto info = make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    if (Status s = check(api.vkCreateBuffer(device, &info, allocator, &b.buffer), "vkCreateBuffer");
        !s)
        return s.error();
    VkMemoryRequirements r{};
    api.vkGetBufferMemoryRequirements(device, b.buffer, &r);
    auto m = allocate(
        r, hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                       : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (!m) {
        destroy(b);
        return m.error();
    }
    b.memory = *m;
    Status s = check(api.vkBindBufferMemory(device, b.buffer, b.memory, 0), "vkBindBufferMemory");
    if (s && hostVisible)
        s = check(api.vkMapMemory(device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
    if (!s) {
        destroy(b);
        return s.error();
    }
    return b;
}

Result<Image> Device::makeImage(VkFormat format, std::uint32_t width, std::uint32_t height,
                                VkImageUsageFlags usage) const {
    Image i;
    auto info = make<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (Status s = check(api.vkCreateImage(device, &info, allocator, &i.image), "vkCreateImage");
        !s)
        return s.error();
    VkMemoryRequirements r{};
    api.vkGetImageMemoryRequirements(device, i.image, &r);
    auto m = allocate(r, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (!m) {
        destroy(i);
        return m.error();
    }
    i.memory = *m;
    Status s = check(api.vkBindImageMemory(device, i.image, i.memory, 0), "vkBindImageMemory");
    if (s) {
        auto v = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        v.image = i.image;
        v.viewType = VK_IMAGE_VIEW_TYPE_2D;
        v.format = format;
        v.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        s = check(api.vkCreateImageView(device, &v, allocator, &i.view), "vkCreateImageView");
    }
    if (!s) {
        destroy(i);
        return s.error();
    }
    return i;
}

Result<VkShaderModule> Device::makeShader(const unsigned char* spirv, std::size_t size) const {
    // The embedded bytes carry no alignment promise; Vulkan reads 32-bit words.
    std::vector<std::uint32_t> words(size / 4);
    std::memcpy(words.data(), spirv, words.size() * 4);
    auto info = make<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = words.size() * 4;
    info.pCode = words.data();
    VkShaderModule module = VK_NULL_HANDLE;
    if (Status s = check(api.vkCreateShaderModule(device, &info, allocator, &module),
                         "vkCreateShaderModule");
        !s)
        return s.error();
    return module;
}

Result<VkSampler> Device::makeSampler(VkFilter filter) const {
    auto info = make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    info.magFilter = info.minFilter = filter;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    // A clear border: sprites fade to nothing past their edge, as on GL.
    info.addressModeU = info.addressModeV = info.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    info.maxLod = 0;
    VkSampler s = VK_NULL_HANDLE;
    if (Status st = check(api.vkCreateSampler(device, &info, allocator, &s), "vkCreateSampler");
        !st)
        return st.error();
    return s;
}

Result<VkPipeline> Device::makePipeline(const PipelineDesc& p) const {
    VkPipelineShaderStageCreateInfo stages[2] = {
        make<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO),
        make<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO)};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = p.vertex;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = p.fragment;
    stages[1].pName = "main";
    const VkVertexInputBindingDescription binding{0, p.vertexStride, VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
    auto input = make<VkPipelineVertexInputStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
    if (p.vertexStride) {
        input.vertexBindingDescriptionCount = input.vertexAttributeDescriptionCount = 1;
        input.pVertexBindingDescriptions = &binding;
        input.pVertexAttributeDescriptions = &position;
    }
    auto assembly = make<VkPipelineInputAssemblyStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
    assembly.topology = p.topology;
    auto viewport = make<VkPipelineViewportStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
    viewport.viewportCount = viewport.scissorCount = 1;
    auto clipControl = make<VkPipelineViewportDepthClipControlCreateInfoEXT>(
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_DEPTH_CLIP_CONTROL_CREATE_INFO_EXT);
    clipControl.negativeOneToOne = VK_TRUE;
    if (p.negativeOneToOne) viewport.pNext = &clipControl;
    auto raster = make<VkPipelineRasterizationStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    // The same clip-space triangle faces the same way in GL and Vulkan (Vulkan's facing sum
    // carries a sign for its y-down framebuffer): counter-clockwise fronts, as the meshes have.
    raster.cullMode = p.cull;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.f;
    auto multisample = make<VkPipelineMultisampleStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
    multisample.rasterizationSamples = p.samples;
    auto depthState = make<VkPipelineDepthStencilStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
    depthState.depthTestEnable = depthState.depthWriteEnable =
        p.depth != VK_FORMAT_UNDEFINED ? VK_TRUE : VK_FALSE;
    depthState.depthCompareOp = p.depthCompare;
    VkPipelineColorBlendAttachmentState blendState{};
    blendState.blendEnable = p.blend != PipelineDesc::Blend::None ? VK_TRUE : VK_FALSE;
    if (p.blend == PipelineDesc::Blend::Add) {
        // Premultiplied sprites added to the HDR colour, its alpha kept (the GL engine's blend).
        blendState.srcColorBlendFactor = blendState.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
        blendState.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
        blendState.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    } else {
        // Multiply: the tile x the source (a translucent occluder's 1 - opacity).
        blendState.srcColorBlendFactor = blendState.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
        blendState.dstColorBlendFactor = blendState.dstAlphaBlendFactor = VK_BLEND_FACTOR_SRC_COLOR;
    }
    blendState.colorBlendOp = blendState.alphaBlendOp = VK_BLEND_OP_ADD;
    blendState.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    auto blend = make<VkPipelineColorBlendStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
    blend.attachmentCount = p.color != VK_FORMAT_UNDEFINED ? 1 : 0;
    blend.pAttachments = &blendState;
    const VkDynamicState dynamic[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    auto dynamicState = make<VkPipelineDynamicStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
    dynamicState.dynamicStateCount = 2;
    dynamicState.pDynamicStates = dynamic;
    auto rendering =
        make<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
    rendering.colorAttachmentCount = blend.attachmentCount;
    rendering.pColorAttachmentFormats = &p.color;
    rendering.depthAttachmentFormat = p.depth;
    auto info = make<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
    info.pNext = &rendering;
    info.stageCount = p.fragment ? 2 : 1;
    info.pStages = stages;
    info.pVertexInputState = &input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depthState;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamicState;
    info.layout = p.layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (Status s = check(
            api.vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, allocator, &pipeline),
            "vkCreateGraphicsPipelines");
        !s)
        return s.error();
    return pipeline;
}

void Device::destroy(Buffer& b) const {
    if (b.buffer) api.vkDestroyBuffer(device, b.buffer, allocator);
    if (b.memory) api.vkFreeMemory(device, b.memory, allocator);  // unmaps too
    b = Buffer{};
}

void Device::destroy(Image& i) const {
    if (i.view) api.vkDestroyImageView(device, i.view, allocator);
    if (i.image) api.vkDestroyImage(device, i.image, allocator);
    if (i.memory) api.vkFreeMemory(device, i.memory, allocator);
    i = Image{};
}

}  // namespace flarekit::vk
