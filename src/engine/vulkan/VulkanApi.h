// SPDX-License-Identifier: Apache-2.0
// The Vulkan functions the engine's Vulkan backend calls, loaded from the application's
// instance and device (vkGetInstanceProcAddr, then vkGetDeviceProcAddr): the library links no
// Vulkan loader, and a GL-only application never needs one.
#pragma once

#ifndef VK_NO_PROTOTYPES
#define VK_NO_PROTOTYPES
#endif
#include <vulkan/vulkan.h>

#include <string>

#include "flarekit/Result.h"

namespace flarekit::vk {

// Instance-level functions (physical-device queries).
#define FLAREKIT_VK_INSTANCE_FUNCTIONS(X)  \
    X(vkGetDeviceProcAddr)                 \
    X(vkGetPhysicalDeviceMemoryProperties) \
    X(vkGetPhysicalDeviceProperties)       \
    X(vkGetPhysicalDeviceFormatProperties)

// Device-level functions.
#define FLAREKIT_VK_DEVICE_FUNCTIONS(X) \
    X(vkCreateBuffer)                   \
    X(vkDestroyBuffer)                  \
    X(vkGetBufferMemoryRequirements)    \
    X(vkAllocateMemory)                 \
    X(vkFreeMemory)                     \
    X(vkBindBufferMemory)               \
    X(vkMapMemory)                      \
    X(vkUnmapMemory)                    \
    X(vkCreateImage)                    \
    X(vkDestroyImage)                   \
    X(vkGetImageMemoryRequirements)     \
    X(vkBindImageMemory)                \
    X(vkCreateImageView)                \
    X(vkDestroyImageView)               \
    X(vkCreateSampler)                  \
    X(vkDestroySampler)                 \
    X(vkCreateShaderModule)             \
    X(vkDestroyShaderModule)            \
    X(vkCreateDescriptorSetLayout)      \
    X(vkDestroyDescriptorSetLayout)     \
    X(vkCreatePipelineLayout)           \
    X(vkDestroyPipelineLayout)          \
    X(vkCreateComputePipelines)         \
    X(vkCreateGraphicsPipelines)        \
    X(vkDestroyPipeline)                \
    X(vkCreateDescriptorPool)           \
    X(vkDestroyDescriptorPool)          \
    X(vkResetDescriptorPool)            \
    X(vkAllocateDescriptorSets)         \
    X(vkUpdateDescriptorSets)           \
    X(vkCmdPipelineBarrier)             \
    X(vkCmdUpdateBuffer)                \
    X(vkCmdBindPipeline)                \
    X(vkCmdBindDescriptorSets)          \
    X(vkCmdDispatch)                    \
    X(vkCmdDraw)                        \
    X(vkCmdSetViewport)                 \
    X(vkCmdSetScissor)                  \
    X(vkCmdCopyBufferToImage)

struct Api {
#define FLAREKIT_VK_MEMBER(name) PFN_##name name = nullptr;
    FLAREKIT_VK_INSTANCE_FUNCTIONS(FLAREKIT_VK_MEMBER)
    FLAREKIT_VK_DEVICE_FUNCTIONS(FLAREKIT_VK_MEMBER)
#undef FLAREKIT_VK_MEMBER
    //! Vulkan 1.3's, or VK_KHR_dynamic_rendering's.
    PFN_vkCmdBeginRendering vkCmdBeginRendering = nullptr;
    PFN_vkCmdEndRendering vkCmdEndRendering = nullptr;
};

//! Every function above for `device` of `instance`; `getInstanceProcAddr` null: the system
//! loader's (libvulkan.so.1, opened on first use). Names the first missing function.
Result<Api> loadApi(PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkInstance instance,
                    VkDevice device);

//! The system loader's vkGetInstanceProcAddr, or null with `why` set.
PFN_vkGetInstanceProcAddr systemLoader(std::string* why);

//! A VkResult as its name, for messages.
std::string resultName(VkResult r);

}  // namespace flarekit::vk
