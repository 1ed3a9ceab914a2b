// SPDX-License-Identifier: Apache-2.0
// The state behind VulkanHost, shared by its three files: VulkanHost.cpp (the instance, device,
// submission and images), VulkanDepthPass.cpp (a scene's depth, as an application's depth
// pre-pass) and VulkanOccluders.cpp (a scene's objects in sun-map tiles).
#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "engine/vulkan/VulkanHost.h"

namespace flarekit::vk {

// What the host calls besides the engine's functions (Api).
#define FLAREKIT_VK_HOST_GLOBAL(X) \
    X(vkCreateInstance)            \
    X(vkEnumerateInstanceLayerProperties)
#define FLAREKIT_VK_HOST_INSTANCE(X)            \
    X(vkDestroyInstance)                        \
    X(vkEnumeratePhysicalDevices)               \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkCreateDevice)                           \
    X(vkEnumerateDeviceExtensionProperties)
#define FLAREKIT_VK_HOST_DEVICE(X) \
    X(vkDestroyDevice)             \
    X(vkGetDeviceQueue)            \
    X(vkCreateCommandPool)         \
    X(vkDestroyCommandPool)        \
    X(vkAllocateCommandBuffers)    \
    X(vkFreeCommandBuffers)        \
    X(vkBeginCommandBuffer)        \
    X(vkEndCommandBuffer)          \
    X(vkQueueSubmit)               \
    X(vkQueueWaitIdle)             \
    X(vkCmdCopyImageToBuffer)      \
    X(vkCmdBindVertexBuffers)      \
    X(vkCmdPushConstants)          \
    X(vkCreateQueryPool)           \
    X(vkDestroyQueryPool)          \
    X(vkCmdResetQueryPool)         \
    X(vkCmdWriteTimestamp)         \
    X(vkGetQueryPoolResults)

struct HostApi {
#define FLAREKIT_VK_MEMBER(name) PFN_##name name = nullptr;
    FLAREKIT_VK_HOST_GLOBAL(FLAREKIT_VK_MEMBER)
    FLAREKIT_VK_HOST_INSTANCE(FLAREKIT_VK_MEMBER)
    FLAREKIT_VK_HOST_DEVICE(FLAREKIT_VK_MEMBER)
#undef FLAREKIT_VK_MEMBER
    PFN_vkCreateDebugUtilsMessengerEXT vkCreateDebugUtilsMessengerEXT = nullptr;
    PFN_vkDestroyDebugUtilsMessengerEXT vkDestroyDebugUtilsMessengerEXT = nullptr;
};

//! What the validation layer said (warnings and errors).
struct Messages {
    std::mutex lock;
    int count = 0;
    std::string first;
};

struct VulkanHost::Impl {
    PFN_vkGetInstanceProcAddr gipa = nullptr;
    HostApi h;
    Device d;
    std::uint32_t family = 0;
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    Messages messages;
    bool clipControl = false;  //!< VK_EXT_depth_clip_control is on
    VkPipelineLayout depthLayout = VK_NULL_HANDLE;
    std::vector<std::pair<std::uint64_t, VkPipeline>> depthPipelines;  //!< by format, samples, Z

    ~Impl() {
        for (auto& [key, p] : depthPipelines) d.api.vkDestroyPipeline(d.device, p, nullptr);
        if (depthLayout) d.api.vkDestroyPipelineLayout(d.device, depthLayout, nullptr);
        if (pool) h.vkDestroyCommandPool(d.device, pool, nullptr);
        if (d.device) h.vkDestroyDevice(d.device, nullptr);
        if (messenger && h.vkDestroyDebugUtilsMessengerEXT)
            h.vkDestroyDebugUtilsMessengerEXT(d.instance, messenger, nullptr);
        if (d.instance) h.vkDestroyInstance(d.instance, nullptr);
    }
    Result<VkPipeline> depthPipeline(VkFormat format, int samples, fk_depth_convention convention);
};

}  // namespace flarekit::vk
