// SPDX-License-Identifier: Apache-2.0
// A headless Vulkan application for flarekit's own use (VulkanHost.h): the instance, the
// device, one-shot submission and the images the CLI and the tests hand the engine.
#include <cstring>

#include "core/HalfFloat.h"
#include "engine/vulkan/VulkanHostImpl.h"

namespace flarekit::vk {

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                         VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data,
                                         void* user) {
    auto* m = static_cast<Messages*>(user);
    const std::lock_guard<std::mutex> guard(m->lock);
    if (m->count++ == 0) m->first = data && data->pMessage ? data->pMessage : "(no text)";
    return VK_FALSE;
}

}  // namespace

VulkanHost::VulkanHost(std::unique_ptr<Impl> impl) : m(std::move(impl)), m_device(&m->d) {}
VulkanHost::~VulkanHost() = default;

Result<std::unique_ptr<VulkanHost>> VulkanHost::create(bool validation) {
    auto m = std::make_unique<Impl>();
    std::string why;
    m->gipa = systemLoader(&why);
    if (!m->gipa) return invalidInput("--backend vulkan: " + why);
    HostApi& h = m->h;
#define FLAREKIT_VK_LOAD(name) h.name = reinterpret_cast<PFN_##name>(m->gipa(nullptr, #name));
    FLAREKIT_VK_HOST_GLOBAL(FLAREKIT_VK_LOAD)
#undef FLAREKIT_VK_LOAD
    if (!h.vkCreateInstance)
        return invalidInput("--backend vulkan: the loader has no vkCreateInstance");
    const char* layer = "VK_LAYER_KHRONOS_validation";
    if (validation) {
        std::uint32_t n = 0;
        h.vkEnumerateInstanceLayerProperties(&n, nullptr);
        std::vector<VkLayerProperties> layers(n);
        h.vkEnumerateInstanceLayerProperties(&n, layers.data());
        bool found = false;
        for (const VkLayerProperties& l : layers) found |= std::strcmp(l.layerName, layer) == 0;
        if (!found)
            return invalidInput("Vulkan validation: VK_LAYER_KHRONOS_validation is not installed");
    }
    auto app = make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "flarekit";
    app.apiVersion = VK_API_VERSION_1_3;
    auto messengerInfo = make<VkDebugUtilsMessengerCreateInfoEXT>(
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &onMessage;
    messengerInfo.pUserData = &m->messages;
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    auto instanceInfo = make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    instanceInfo.pApplicationInfo = &app;
    if (validation) {
        instanceInfo.enabledLayerCount = 1;
        instanceInfo.ppEnabledLayerNames = &layer;
        instanceInfo.enabledExtensionCount = 1;
        instanceInfo.ppEnabledExtensionNames = &extension;
        instanceInfo.pNext = &messengerInfo;  // instance creation itself is checked too
    }
    if (Status s =
            check(h.vkCreateInstance(&instanceInfo, nullptr, &m->d.instance), "vkCreateInstance");
        !s)
        return invalidInput("--backend vulkan: no Vulkan driver (" + s.error().message + ")");
    const VkInstance instance = m->d.instance;
#define FLAREKIT_VK_LOAD(name) h.name = reinterpret_cast<PFN_##name>(m->gipa(instance, #name));
    FLAREKIT_VK_HOST_INSTANCE(FLAREKIT_VK_LOAD)
#undef FLAREKIT_VK_LOAD
    if (validation) {
        h.vkCreateDebugUtilsMessengerEXT = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            m->gipa(instance, "vkCreateDebugUtilsMessengerEXT"));
        h.vkDestroyDebugUtilsMessengerEXT = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            m->gipa(instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (h.vkCreateDebugUtilsMessengerEXT)
            h.vkCreateDebugUtilsMessengerEXT(instance, &messengerInfo, nullptr, &m->messenger);
    }
    std::uint32_t count = 0;
    h.vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> physical(count);
    h.vkEnumeratePhysicalDevices(instance, &count, physical.data());
    // The first device with a graphics-and-compute queue family.
    for (VkPhysicalDevice p : physical) {
        std::uint32_t families = 0;
        h.vkGetPhysicalDeviceQueueFamilyProperties(p, &families, nullptr);
        std::vector<VkQueueFamilyProperties> props(families);
        h.vkGetPhysicalDeviceQueueFamilyProperties(p, &families, props.data());
        for (std::uint32_t f = 0; f < families && !m->d.physical; ++f) {
            constexpr VkQueueFlags kBoth = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
            if ((props[f].queueFlags & kBoth) == kBoth) m->d.physical = p, m->family = f;
        }
        if (m->d.physical) break;
    }
    if (!m->d.physical)
        return invalidInput("--backend vulkan: no Vulkan device with a graphics and compute queue");
    const float priority = 1.f;
    auto queueInfo = make<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queueInfo.queueFamilyIndex = m->family;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    auto features13 = make<VkPhysicalDeviceVulkan13Features>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    features13.dynamicRendering = VK_TRUE;
    // Classic GL depth ([-1, 1] clip z) for FK_DEPTH_MINUS_ONE_TO_ONE frames, where the device
    // has it (VK_EXT_depth_clip_control).
    std::uint32_t extensionCount = 0;
    h.vkEnumerateDeviceExtensionProperties(m->d.physical, nullptr, &extensionCount, nullptr);
    std::vector<VkExtensionProperties> extensions(extensionCount);
    h.vkEnumerateDeviceExtensionProperties(m->d.physical, nullptr, &extensionCount,
                                           extensions.data());
    const char* clipControlName = VK_EXT_DEPTH_CLIP_CONTROL_EXTENSION_NAME;
    for (const VkExtensionProperties& e : extensions)
        m->clipControl |= std::strcmp(e.extensionName, clipControlName) == 0;
    auto clipControl = make<VkPhysicalDeviceDepthClipControlFeaturesEXT>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_CLIP_CONTROL_FEATURES_EXT);
    clipControl.depthClipControl = VK_TRUE;
    if (m->clipControl) features13.pNext = &clipControl;
    auto deviceInfo = make<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    deviceInfo.pNext = &features13;
    if (m->clipControl) {
        deviceInfo.enabledExtensionCount = 1;
        deviceInfo.ppEnabledExtensionNames = &clipControlName;
    }
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    if (Status s = check(h.vkCreateDevice(m->d.physical, &deviceInfo, nullptr, &m->d.device),
                         "vkCreateDevice");
        !s)
        return invalidInput("--backend vulkan: the device needs Vulkan 1.3 (" + s.error().message +
                            ")");
    auto api = loadApi(m->gipa, instance, m->d.device);
    if (!api) return api.error();
    m->d.api = *api;
    m->d.api.vkGetPhysicalDeviceMemoryProperties(m->d.physical, &m->d.memory);
    m->d.api.vkGetPhysicalDeviceProperties(m->d.physical, &m->d.properties);
    const VkDevice device = m->d.device;
#define FLAREKIT_VK_LOAD(name) \
    h.name = reinterpret_cast<PFN_##name>(m->d.api.vkGetDeviceProcAddr(device, #name));
    FLAREKIT_VK_HOST_DEVICE(FLAREKIT_VK_LOAD)
#undef FLAREKIT_VK_LOAD
    h.vkGetDeviceQueue(device, m->family, 0, &m->queue);
    auto poolInfo = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = m->family;
    if (Status s = check(h.vkCreateCommandPool(device, &poolInfo, nullptr, &m->pool),
                         "vkCreateCommandPool");
        !s)
        return s.error();
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT, 0, 64};
    auto layoutInfo =
        make<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &range;
    if (Status s =
            check(m->d.api.vkCreatePipelineLayout(device, &layoutInfo, nullptr, &m->depthLayout),
                  "vkCreatePipelineLayout");
        !s)
        return s.error();
    return std::unique_ptr<VulkanHost>(new VulkanHost(std::move(m)));
}

fk_vulkan_device VulkanHost::engineDevice(int framesInFlight) const {
    fk_vulkan_device d{};
    d.instance = m->d.instance;
    d.physical_device = m->d.physical;
    d.device = m->d.device;
    d.queue_family_index = m->family;
    d.get_instance_proc_addr = m->gipa;
    d.frames_in_flight = framesInFlight;
    return d;
}

Status VulkanHost::submit(const std::function<void(VkCommandBuffer)>& record) {
    const HostApi& h = m->h;
    auto alloc = make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = m->pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (Status s = check(h.vkAllocateCommandBuffers(m->d.device, &alloc, &cmd),
                         "vkAllocateCommandBuffers");
        !s)
        return s;
    auto begin = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    h.vkBeginCommandBuffer(cmd, &begin);
    record(cmd);
    Status s = check(h.vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    if (s) {
        auto submitInfo = make<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
        submitInfo.commandBufferCount = 1;
        submitInfo.pCommandBuffers = &cmd;
        s = check(h.vkQueueSubmit(m->queue, 1, &submitInfo, VK_NULL_HANDLE), "vkQueueSubmit");
        if (s) s = check(h.vkQueueWaitIdle(m->queue), "vkQueueWaitIdle");
    }
    h.vkFreeCommandBuffers(m->d.device, m->pool, 1, &cmd);
    return s;
}

Result<double> VulkanHost::submitTimed(const std::function<void(VkCommandBuffer)>& record) {
    const HostApi& h = m->h;
    auto info = make<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2;
    VkQueryPool pool = VK_NULL_HANDLE;
    if (Status s =
            check(h.vkCreateQueryPool(m->d.device, &info, nullptr, &pool), "vkCreateQueryPool");
        !s)
        return s.error();
    Status s = submit([&](VkCommandBuffer cmd) {
        h.vkCmdResetQueryPool(cmd, pool, 0, 2);
        h.vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool, 0);
        record(cmd);
        h.vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool, 1);
    });
    std::uint64_t ticks[2] = {0, 0};
    if (s)
        s = check(
            h.vkGetQueryPoolResults(m->d.device, pool, 0, 2, sizeof ticks, ticks, sizeof ticks[0],
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
            "vkGetQueryPoolResults");
    h.vkDestroyQueryPool(m->d.device, pool, nullptr);
    if (!s) return s.error();
    return double(ticks[1] - ticks[0]) * double(m->d.properties.limits.timestampPeriod) * 1e-6;
}

Result<Image> VulkanHost::upload(VkFormat format, int width, int height, const float* rgba,
                                 VkImageUsageFlags usage, VkImageLayout layout,
                                 VkPipelineStageFlags stage, VkAccessFlags access) {
    const Device& d = m->d;
    const bool half = format == VK_FORMAT_R16G16B16A16_SFLOAT;
    if (!half && format != VK_FORMAT_R32G32B32A32_SFLOAT)
        return internalError("VulkanHost: expected an RGBA16F or RGBA32F image");
    auto image = d.makeImage(format, std::uint32_t(width), std::uint32_t(height),
                             usage | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    if (!image) return image.error();
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const VkDeviceSize bytes = VkDeviceSize(pixels) * (half ? 8 : 16);
    auto staging = d.makeBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    if (!staging) {
        d.destroy(*image);
        return staging.error();
    }
    if (!rgba)
        std::memset(staging->mapped, 0, bytes);
    else if (half)
        floatsToHalf(rgba, pixels, 4, static_cast<std::uint16_t*>(staging->mapped));
    else
        std::memcpy(staging->mapped, rgba, bytes);
    const VkImage target = image->image;
    Status s = submit([&](VkCommandBuffer cmd) {
        imageBarrier(d.api, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {std::uint32_t(width), std::uint32_t(height), 1};
        d.api.vkCmdCopyBufferToImage(cmd, staging->buffer, target,
                                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        imageBarrier(d.api, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, layout, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, stage, access);
    });
    d.destroy(*staging);
    if (!s) {
        d.destroy(*image);
        return s.error();
    }
    return *image;
}

Result<Image> VulkanHost::colorImage(VkFormat format, int width, int height, const float* rgba) {
    return upload(format, width, height, rgba,
                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
}

Result<Image> VulkanHost::sampledImage(int width, int height, const float* rgba) {
    return upload(VK_FORMAT_R16G16B16A16_SFLOAT, width, height, rgba, VK_IMAGE_USAGE_SAMPLED_BIT,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT);
}

Result<std::vector<float>> VulkanHost::readColor(const Image& image, int width, int height) {
    const Device& d = m->d;
    const VkDeviceSize bytes = VkDeviceSize(width) * VkDeviceSize(height) * 16;
    auto staging = d.makeBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    if (!staging) return staging.error();
    Status s = submit([&](VkCommandBuffer cmd) {
        imageBarrier(d.api, cmd, image.image, VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {std::uint32_t(width), std::uint32_t(height), 1};
        m->h.vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                    staging->buffer, 1, &region);
        imageBarrier(d.api, cmd, image.image, VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        auto host = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        d.api.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                                   0, 1, &host, 0, nullptr, 0, nullptr);
    });
    std::vector<float> pixels;
    if (s) {
        pixels.resize(std::size_t(width) * std::size_t(height) * 4);
        std::memcpy(pixels.data(), staging->mapped, bytes);
    }
    d.destroy(*staging);
    if (!s) return s.error();
    return pixels;
}

int VulkanHost::validationMessages() const {
    const std::lock_guard<std::mutex> guard(m->messages.lock);
    return m->messages.count;
}

std::string VulkanHost::firstValidationMessage() const {
    const std::lock_guard<std::mutex> guard(m->messages.lock);
    return m->messages.first;
}

std::string VulkanHost::deviceName() const {
    return m->d.properties.deviceName;
}

}  // namespace flarekit::vk
