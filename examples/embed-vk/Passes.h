// SPDX-License-Identifier: Apache-2.0
// embed-vk's own passes: the sky and the city into the 4x MSAA HDR targets, and the tone map of
// the resolved HDR colour (after flarekit added its flares) into the 8-bit frame; their layouts,
// the tone map's descriptor set and the shaders (glslc's SPIR-V, embedded at build time).
#pragma once

#include <array>

#include "Gpu.h"
#include "embed_vk_shaders.h"

struct Passes {
    VkPushConstantRange push{};  //!< the sky's and the city's: 80 bytes
    VkPipelineLayout sceneLayout = VK_NULL_HANDLE, tonemapLayout = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet hdrSet = VK_NULL_HANDLE;  //!< the resolved HDR colour, for the tone map
    std::array<VkShaderModule, 5> shaders{};
    VkPipeline scene = VK_NULL_HANDLE, sky = VK_NULL_HANDLE, tonemap = VK_NULL_HANDLE;
};

//! The passes for targets of these formats, the tone map reading `hdrView`.
inline Passes makePasses(const Gpu& g, VkImageView hdrView, VkFormat hdr, VkFormat depth,
                         VkSampleCountFlagBits msaa, VkFormat ldr) {
    namespace s = embed_vk_shaders;
    Passes ps;
    ps.push = {VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, 80};
    VkPipelineLayoutCreateInfo pushLayout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pushLayout.pushConstantRangeCount = 1;
    pushLayout.pPushConstantRanges = &ps.push;
    check(vkCreatePipelineLayout(g.device, &pushLayout, nullptr, &ps.sceneLayout), "layout");
    VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    samplerInfo.magFilter = samplerInfo.minFilter = VK_FILTER_LINEAR;
    samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    check(vkCreateSampler(g.device, &samplerInfo, nullptr, &ps.sampler), "sampler");
    const VkDescriptorSetLayoutBinding hdrBinding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                                  VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = 1;
    setInfo.pBindings = &hdrBinding;
    check(vkCreateDescriptorSetLayout(g.device, &setInfo, nullptr, &ps.setLayout), "set layout");
    VkPipelineLayoutCreateInfo tonemapLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    tonemapLayoutInfo.setLayoutCount = 1;
    tonemapLayoutInfo.pSetLayouts = &ps.setLayout;
    check(vkCreatePipelineLayout(g.device, &tonemapLayoutInfo, nullptr, &ps.tonemapLayout),
          "layout");
    const VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &poolSize;
    check(vkCreateDescriptorPool(g.device, &poolInfo, nullptr, &ps.pool), "pool");
    VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocInfo.descriptorPool = ps.pool;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &ps.setLayout;
    check(vkAllocateDescriptorSets(g.device, &allocInfo, &ps.hdrSet), "set");
    const VkDescriptorImageInfo hdrImage{ps.sampler, hdrView,
                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet writeSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writeSet.dstSet = ps.hdrSet;
    writeSet.descriptorCount = 1;
    writeSet.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writeSet.pImageInfo = &hdrImage;
    vkUpdateDescriptorSets(g.device, 1, &writeSet, 0, nullptr);

    ps.shaders = {shader(g, s::scene_vert, sizeof s::scene_vert),
                  shader(g, s::scene_frag, sizeof s::scene_frag),
                  shader(g, s::fullscreen_vert, sizeof s::fullscreen_vert),
                  shader(g, s::sky_frag, sizeof s::sky_frag),
                  shader(g, s::tonemap_frag, sizeof s::tonemap_frag)};
    const auto& [sceneVert, sceneFrag, fullVert, skyFrag, toneFrag] = ps.shaders;
    ps.scene = pipeline(g, ps.sceneLayout, sceneVert, sceneFrag, true, hdr, depth, msaa);
    ps.sky = pipeline(g, ps.sceneLayout, fullVert, skyFrag, false, hdr, depth, msaa);
    ps.tonemap = pipeline(g, ps.tonemapLayout, fullVert, toneFrag, false, ldr, VK_FORMAT_UNDEFINED,
                          VK_SAMPLE_COUNT_1_BIT);
    return ps;
}

inline void destroy(const Gpu& g, const Passes& ps) {
    for (VkPipeline pl : {ps.scene, ps.sky, ps.tonemap}) vkDestroyPipeline(g.device, pl, nullptr);
    for (VkShaderModule m : ps.shaders) vkDestroyShaderModule(g.device, m, nullptr);
    vkDestroyDescriptorPool(g.device, ps.pool, nullptr);
    vkDestroyPipelineLayout(g.device, ps.sceneLayout, nullptr);
    vkDestroyPipelineLayout(g.device, ps.tonemapLayout, nullptr);
    vkDestroyDescriptorSetLayout(g.device, ps.setLayout, nullptr);
    vkDestroySampler(g.device, ps.sampler, nullptr);
}
