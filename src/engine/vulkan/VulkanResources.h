// SPDX-License-Identifier: Apache-2.0
// The Vulkan backend's buffers, images and the one-time objects made from them (shader
// modules, samplers), each with the device memory it owns, created and destroyed through the
// application's device and allocator.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/vulkan/VulkanApi.h"
#include "flarekit/Result.h"

namespace flarekit::vk {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;  //!< host-visible buffers stay mapped
    VkDeviceSize size = 0;
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

//! A graphics pipeline for dynamic rendering, with viewport and scissor dynamic: the few
//! things the backend's and its host's pipelines differ in.
struct PipelineDesc {
    VkShaderModule vertex = VK_NULL_HANDLE, fragment = VK_NULL_HANDLE;  //!< fragment optional
    std::uint32_t vertexStride = 0;  //!< a vec3 position at location 0 of this stride (0: none)
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkCullModeFlags cull = VK_CULL_MODE_NONE;  //!< counter-clockwise fronts
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    enum class Blend { None, Add, Multiply } blend = Blend::None;  //!< Add: rgb ONE+ONE, alpha kept
    VkFormat color = VK_FORMAT_UNDEFINED, depth = VK_FORMAT_UNDEFINED;
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS;  //!< with a depth format: test and write
    //! Clip z in [-1, 1], as classic GL (VK_EXT_depth_clip_control, enabled on the device).
    bool negativeOneToOne = false;
    VkPipelineLayout layout = VK_NULL_HANDLE;
};

//! The device and what creating objects on it needs.
struct Device {
    Api api;
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    const VkAllocationCallbacks* allocator = nullptr;
    VkPhysicalDeviceMemoryProperties memory{};
    VkPhysicalDeviceProperties properties{};

    //! A buffer of `usage`; host-visible and mapped (coherent) or device-local.
    Result<Buffer> makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible) const;
    //! A single-sample 2D colour image of `format` with a view of it.
    Result<Image> makeImage(VkFormat format, std::uint32_t width, std::uint32_t height,
                            VkImageUsageFlags usage) const;
    Result<VkShaderModule> makeShader(const unsigned char* spirv, std::size_t size) const;
    Result<VkSampler> makeSampler(VkFilter filter) const;
    Result<VkPipeline> makePipeline(const PipelineDesc& desc) const;
    void destroy(Buffer& b) const;
    void destroy(Image& i) const;

  private:
    Result<VkDeviceMemory> allocate(const VkMemoryRequirements& r,
                                    VkMemoryPropertyFlags wanted) const;
};

//! A zeroed Vulkan structure of type `type` (its sType set), for filling field by field.
template <class T>
T make(VkStructureType type) {
    T v{};
    v.sType = type;
    return v;
}

//! One descriptor of `set` at `binding`: a buffer (`buffer`) or an image (`image`), the other
//! null.
inline VkWriteDescriptorSet descriptorWrite(VkDescriptorSet set, std::uint32_t binding,
                                            VkDescriptorType type,
                                            const VkDescriptorBufferInfo* buffer,
                                            const VkDescriptorImageInfo* image) {
    auto w = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pBufferInfo = buffer;
    w.pImageInfo = image;
    return w;
}

//! One image's layout change (aspect `aspect`, its only level and layer), ordered after what
//! `srcStage` did with `srcAccess` and before `dstStage`'s `dstAccess`.
void imageBarrier(const Api& api, VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                  VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

//! `call`'s name and result as an internal error (a driver refusal), or Ok.
Status check(VkResult result, const char* call);

}  // namespace flarekit::vk
