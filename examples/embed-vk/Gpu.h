// SPDX-License-Identifier: Apache-2.0
// embed-vk's Vulkan plumbing, as any small Vulkan application has its own: the instance and
// device (validation on request), images, buffers, layout transitions and pipelines for dynamic
// rendering. Nothing here is flarekit's; main.cpp draws the city and calls flarekit.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "../embed-gl/CityMesh.h"

inline int fail(const char* what, VkResult r = VK_SUCCESS) {
    std::fprintf(stderr, "embed-vk: %s%s%d%s\n", what, r ? " (VkResult " : "", int(r),
                 r ? ")" : "");
    std::exit(1);
}

inline void check(VkResult r, const char* what) {
    if (r != VK_SUCCESS) fail(what, r);
}

inline int g_validationMessages = 0;

inline VKAPI_ATTR VkBool32 VKAPI_CALL onValidation(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void*) {
    ++g_validationMessages;
    std::fprintf(stderr, "embed-vk: validation: %s\n", data->pMessage);
    return VK_FALSE;
}

//! The application's device: instance, the first device with a graphics queue, Vulkan 1.3's
//! dynamic rendering on.
struct Gpu {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t family = 0;
    VkQueue queue = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory{};

    //! The instance, with `extensions` (a window system's surface extensions, if any).
    Gpu(bool validate, std::vector<const char*> extensions) {
        VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
        app.pApplicationName = "embed-vk";
        app.apiVersion = VK_API_VERSION_1_3;
        VkDebugUtilsMessengerCreateInfoEXT messages{
            VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        messages.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        messages.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
        messages.pfnUserCallback = &onValidation;
        const char* layer = "VK_LAYER_KHRONOS_validation";
        if (validate) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
        info.pApplicationInfo = &app;
        info.enabledExtensionCount = uint32_t(extensions.size());
        info.ppEnabledExtensionNames = extensions.data();
        if (validate) {
            info.pNext = &messages;
            info.enabledLayerCount = 1;
            info.ppEnabledLayerNames = &layer;
        }
        check(vkCreateInstance(&info, nullptr, &instance), "no Vulkan 1.3 instance");
        if (validate) {
            auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
            if (create) create(instance, &messages, nullptr, &messenger);
        }
    }

    //! The first device with a graphics-and-compute queue (that presents to `surface`, if
    //! any), Vulkan 1.3's dynamic rendering on (flarekit's draw begins its own rendering).
    void open(VkSurfaceKHR surface) {
        uint32_t count = 0;
        vkEnumeratePhysicalDevices(instance, &count, nullptr);
        std::vector<VkPhysicalDevice> devices(count);
        vkEnumeratePhysicalDevices(instance, &count, devices.data());
        for (VkPhysicalDevice p : devices) {
            uint32_t n = 0;
            vkGetPhysicalDeviceQueueFamilyProperties(p, &n, nullptr);
            std::vector<VkQueueFamilyProperties> families(n);
            vkGetPhysicalDeviceQueueFamilyProperties(p, &n, families.data());
            for (uint32_t f = 0; f < n && !physical; ++f) {
                VkBool32 presents = VK_TRUE;
                if (surface) vkGetPhysicalDeviceSurfaceSupportKHR(p, f, surface, &presents);
                if ((families[f].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
                        (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT) &&
                    presents)
                    physical = p, family = f;
            }
        }
        if (!physical) fail("no Vulkan device with a graphics queue");
        vkGetPhysicalDeviceMemoryProperties(physical, &memory);
        const float priority = 1.f;
        VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queueInfo.queueFamilyIndex = family;
        queueInfo.queueCount = 1;
        queueInfo.pQueuePriorities = &priority;
        VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        v13.dynamicRendering = VK_TRUE;  // flarekit's draw begins its own rendering
        VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        deviceInfo.pNext = &v13;
        deviceInfo.queueCreateInfoCount = 1;
        deviceInfo.pQueueCreateInfos = &queueInfo;
        const char* swapchain = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
        if (surface)
            deviceInfo.enabledExtensionCount = 1, deviceInfo.ppEnabledExtensionNames = &swapchain;
        check(vkCreateDevice(physical, &deviceInfo, nullptr, &device), "no Vulkan 1.3 device");
        vkGetDeviceQueue(device, family, 0, &queue);
    }
    ~Gpu() {
        if (device) vkDestroyDevice(device, nullptr);
        if (messenger) {
            auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
            if (destroy) destroy(instance, messenger, nullptr);
        }
        vkDestroyInstance(instance, nullptr);
    }

    VkDeviceMemory allocate(VkMemoryRequirements r, VkMemoryPropertyFlags wanted) const {
        for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
            if (!(r.memoryTypeBits & (1u << i)) ||
                (memory.memoryTypes[i].propertyFlags & wanted) != wanted)
                continue;
            VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
            info.allocationSize = r.size;
            info.memoryTypeIndex = i;
            VkDeviceMemory m = VK_NULL_HANDLE;
            check(vkAllocateMemory(device, &info, nullptr, &m), "vkAllocateMemory");
            return m;
        }
        fail("no memory type");
        return VK_NULL_HANDLE;
    }
};

struct Target {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

inline Target makeTarget(const Gpu& g, VkFormat format, int w, int h, VkSampleCountFlagBits samples,
                         VkImageUsageFlags usage, VkImageAspectFlags aspect) {
    Target t;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {uint32_t(w), uint32_t(h), 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = samples;
    info.usage = usage;
    check(vkCreateImage(g.device, &info, nullptr, &t.image), "vkCreateImage");
    VkMemoryRequirements r;
    vkGetImageMemoryRequirements(g.device, t.image, &r);
    t.memory = g.allocate(r, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    vkBindImageMemory(g.device, t.image, t.memory, 0);
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = t.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    check(vkCreateImageView(g.device, &view, nullptr, &t.view), "vkCreateImageView");
    return t;
}

inline void destroy(const Gpu& g, Target& t) {
    vkDestroyImageView(g.device, t.view, nullptr);
    vkDestroyImage(g.device, t.image, nullptr);
    vkFreeMemory(g.device, t.memory, nullptr);
}

inline void transition(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                       VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                       VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                       VkAccessFlags dstAccess) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

inline VkShaderModule shader(const Gpu& g, const unsigned char* code, size_t size) {
    std::vector<uint32_t> words(size / 4);
    std::memcpy(words.data(), code, size);
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = size;
    info.pCode = words.data();
    VkShaderModule m = VK_NULL_HANDLE;
    check(vkCreateShaderModule(g.device, &info, nullptr, &m), "vkCreateShaderModule");
    return m;
}

//! A graphics pipeline for dynamic rendering: `vert` + `frag`, the scene's vertex layout or
//! none, one colour attachment of `color` and optionally a depth one (reversed-Z GREATER).
inline VkPipeline pipeline(const Gpu& g, VkPipelineLayout layout, VkShaderModule vert,
                           VkShaderModule frag, bool sceneVertices, VkFormat color, VkFormat depth,
                           VkSampleCountFlagBits samples) {
    VkPipelineShaderStageCreateInfo stages[2] = {
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT, stages[0].module = vert, stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT, stages[1].module = frag,
    stages[1].pName = "main";
    const VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[3] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12},
        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 24}};
    VkPipelineVertexInputStateCreateInfo input{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (sceneVertices) {
        input.vertexBindingDescriptionCount = 1, input.pVertexBindingDescriptions = &binding;
        input.vertexAttributeDescriptionCount = 3, input.pVertexAttributeDescriptions = attributes;
    }
    VkPipelineInputAssemblyStateCreateInfo assembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.lineWidth = 1.f;
    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = samples;
    VkPipelineDepthStencilStateCreateInfo depthState{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depthState.depthTestEnable = depthState.depthWriteEnable = sceneVertices;
    depthState.depthCompareOp = VK_COMPARE_OP_GREATER;  // reversed Z
    VkPipelineColorBlendAttachmentState write{};
    write.colorWriteMask = 0xf;
    VkPipelineColorBlendStateCreateInfo blend{
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &write;
    const VkDynamicState dynamic[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamicState{
        VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamicState.dynamicStateCount = 2;
    dynamicState.pDynamicStates = dynamic;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &color;
    rendering.depthAttachmentFormat = depth;
    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depthState;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamicState;
    info.layout = layout;
    VkPipeline p = VK_NULL_HANDLE;
    check(vkCreateGraphicsPipelines(g.device, VK_NULL_HANDLE, 1, &info, nullptr, &p),
          "vkCreateGraphicsPipelines");
    return p;
}

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
};

inline Buffer hostBuffer(const Gpu& g, VkDeviceSize size, VkBufferUsageFlags usage) {
    Buffer b;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    check(vkCreateBuffer(g.device, &info, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements r;
    vkGetBufferMemoryRequirements(g.device, b.buffer, &r);
    b.memory =
        g.allocate(r, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vkBindBufferMemory(g.device, b.buffer, b.memory, 0);
    vkMapMemory(g.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped);
    return b;
}

inline void destroy(const Gpu& g, Buffer& b) {
    vkDestroyBuffer(g.device, b.buffer, nullptr);
    vkFreeMemory(g.device, b.memory, nullptr);
}
