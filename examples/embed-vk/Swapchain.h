// SPDX-License-Identifier: Apache-2.0
// embed-vk's window: a FIFO swapchain on the GLFW surface, its images the tone-mapped frame is
// blitted to (TRANSFER_DST) and presented from.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "Gpu.h"

struct Swapchain {
    VkSwapchainKHR chain = VK_NULL_HANDLE;  //!< none without a window
    std::vector<VkImage> images;
    VkExtent2D extent{};
};

//! The swapchain of `surface` (none for VK_NULL_HANDLE), `w` x `h` unless the surface says.
inline Swapchain makeSwapchain(const Gpu& g, VkSurfaceKHR surface, int w, int h) {
    Swapchain sc;
    sc.extent = {uint32_t(w), uint32_t(h)};
    if (!surface) return sc;
    VkSurfaceCapabilitiesKHR caps{};
    vkGetPhysicalDeviceSurfaceCapabilitiesKHR(g.physical, surface, &caps);
    uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(g.physical, surface, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(g.physical, surface, &n, formats.data());
    VkSurfaceFormatKHR format = formats.at(0);
    for (const VkSurfaceFormatKHR& f : formats)
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM) format = f;
    if (caps.currentExtent.width != UINT32_MAX) sc.extent = caps.currentExtent;
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = caps.maxImageCount ? std::min(caps.minImageCount + 1, caps.maxImageCount)
                                            : caps.minImageCount + 1;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = sc.extent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                                            (~caps.supportedCompositeAlpha + 1));
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // every driver has it
    info.clipped = VK_TRUE;
    check(vkCreateSwapchainKHR(g.device, &info, nullptr, &sc.chain), "vkCreateSwapchainKHR");
    vkGetSwapchainImagesKHR(g.device, sc.chain, &n, nullptr);
    sc.images.resize(n);
    vkGetSwapchainImagesKHR(g.device, sc.chain, &n, sc.images.data());
    return sc;
}
