// SPDX-License-Identifier: Apache-2.0
#include "engine/vulkan/VulkanApi.h"

#include <dlfcn.h>

#include <string>

namespace flarekit::vk {

PFN_vkGetInstanceProcAddr systemLoader(std::string* why) {
    // Opened once and kept: the loader stays loaded for the process, as applications keep it.
    static void* loader = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!loader) {
        if (why) *why = "no Vulkan loader (libvulkan.so.1) could be opened";
        return nullptr;
    }
    auto* gipa =
        reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(loader, "vkGetInstanceProcAddr"));
    if (!gipa && why) *why = "libvulkan.so.1 has no vkGetInstanceProcAddr";
    return gipa;
}

Result<Api> loadApi(PFN_vkGetInstanceProcAddr gipa, VkInstance instance, VkDevice device) {
    std::string why;
    if (!gipa) gipa = systemLoader(&why);
    if (!gipa) return invalidInput(why);
    Api a;
    std::string missing;
#define FLAREKIT_VK_LOAD_INSTANCE(name)                           \
    a.name = reinterpret_cast<PFN_##name>(gipa(instance, #name)); \
    if (!a.name && missing.empty()) missing = #name;
    FLAREKIT_VK_INSTANCE_FUNCTIONS(FLAREKIT_VK_LOAD_INSTANCE)
#undef FLAREKIT_VK_LOAD_INSTANCE
    if (!missing.empty()) return invalidInput("instance: expected " + missing + " from it");
#define FLAREKIT_VK_LOAD_DEVICE(name)                                            \
    a.name = reinterpret_cast<PFN_##name>(a.vkGetDeviceProcAddr(device, #name)); \
    if (!a.name && missing.empty()) missing = #name;
    FLAREKIT_VK_DEVICE_FUNCTIONS(FLAREKIT_VK_LOAD_DEVICE)
#undef FLAREKIT_VK_LOAD_DEVICE
    if (!missing.empty()) return invalidInput("device: expected " + missing + " from it");
    a.vkCmdBeginRendering = reinterpret_cast<PFN_vkCmdBeginRendering>(
        a.vkGetDeviceProcAddr(device, "vkCmdBeginRendering"));
    a.vkCmdEndRendering =
        reinterpret_cast<PFN_vkCmdEndRendering>(a.vkGetDeviceProcAddr(device, "vkCmdEndRendering"));
    if (!a.vkCmdBeginRendering || !a.vkCmdEndRendering) {
        a.vkCmdBeginRendering = reinterpret_cast<PFN_vkCmdBeginRendering>(
            a.vkGetDeviceProcAddr(device, "vkCmdBeginRenderingKHR"));
        a.vkCmdEndRendering = reinterpret_cast<PFN_vkCmdEndRendering>(
            a.vkGetDeviceProcAddr(device, "vkCmdEndRenderingKHR"));
    }
    if (!a.vkCmdBeginRendering || !a.vkCmdEndRendering) {
        return invalidInput(
            "device: expected Vulkan 1.3 or VK_KHR_dynamic_rendering (vkCmdBeginRendering)");
    }
    return a;
}

std::string resultName(VkResult r) {
    switch (r) {
#define FLAREKIT_VK_RESULT(name) \
    case name:                   \
        return #name;
        FLAREKIT_VK_RESULT(VK_SUCCESS)
        FLAREKIT_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        FLAREKIT_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        FLAREKIT_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        FLAREKIT_VK_RESULT(VK_ERROR_DEVICE_LOST)
        FLAREKIT_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        FLAREKIT_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        FLAREKIT_VK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        FLAREKIT_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        FLAREKIT_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        FLAREKIT_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        FLAREKIT_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        FLAREKIT_VK_RESULT(VK_ERROR_FRAGMENTED_POOL)
#undef FLAREKIT_VK_RESULT
        default:
            return "VkResult " + std::to_string(int(r));
    }
}

}  // namespace flarekit::vk
