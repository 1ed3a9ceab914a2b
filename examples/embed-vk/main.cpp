// SPDX-License-Identifier: Apache-2.0
// embed-vk: a small Vulkan application with its own instance, device, pipelines, city of street
// lamps, reversed-Z 4x MSAA depth image and frame loop (two frames in flight), which gets lens
// flares from flarekit through the C API alone: each frame it records flarekit's occlusion
// pass on its depth image (fk_engine_record_occlusion) and every light's flare into its HDR
// colour (fk_engine_record_draw) into its own command buffer, then its own tone map.
//   embed-vk [--frames N] [--size WxH] [--out frame.ppm] [--scene-json S] [--coverage-json C]
//            [--validate] [--window | --headless]
// With a display (and GLFW) it opens a window and presents each frame until the window is
// closed (or --frames N frames); --headless, or no display, renders N frames (default 3) off
// screen. Either way the last frame goes to --out (and the last frame's world as a flarekit
// scene, and flarekit's coverage of each light, for `flarekit visibility` to judge).
// --validate turns on the Khronos validation layer and fails (exit 1) on any message.
#include <vulkan/vulkan.h>
#if EMBED_HAS_GLFW
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#endif

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "../embed-gl/CityMesh.h"  // the same city as embed-gl
#include "Gpu.h"
#include "Passes.h"
#include "Swapchain.h"
#include "flarekit/flarekit_vulkan.h"

namespace {

//! Reversed-Z with an infinite far plane (near at depth 1, infinity at 0) and Vulkan's clip
//! space (y down: the y scale is negative).
Mat reversedInfinitePerspective(float fovYDeg, float aspect, float nearPlane) {
    const float f = 1.f / std::tan(fovYDeg * 3.14159265f / 360.f);
    return {f / aspect, 0, 0, 0, 0, -f, 0, 0, 0, 0, 0, -1, 0, 0, nearPlane, 0};
}

struct Options {
    int frames = 3, width = 1280, height = 720;
    std::string out = "embed-vk.ppm", sceneJson, coverageJson;
    bool validate = false, window = false, headless = false, framesGiven = false;
};

bool parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--frames" && more)
            o.frames = std::atoi(argv[++i]), o.framesGiven = true;
        else if (a == "--window")
            o.window = true;
        else if (a == "--headless")
            o.headless = true;
        else if (a == "--size" && more) {
            if (std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2) return false;
        } else if (a == "--out" && more)
            o.out = argv[++i];
        else if (a == "--scene-json" && more)
            o.sceneJson = argv[++i];
        else if (a == "--coverage-json" && more)
            o.coverageJson = argv[++i];
        else if (a == "--validate")
            o.validate = true;
        else
            return false;
    }
    return !(o.window && o.headless) && o.frames >= 1 && o.width >= 16 && o.height >= 16 &&
           o.width <= 8192 && o.height <= 8192;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) {
        std::fprintf(stderr,
                     "usage: embed-vk [--frames N] [--size WxH] [--out F.ppm] [--scene-json S] "
                     "[--coverage-json C] [--validate] [--window | --headless]\n");
        return 2;
    }
    std::vector<const char*> extensions;
#if EMBED_HAS_GLFW
    GLFWwindow* window = nullptr;
    const bool display = std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY");
    const bool asked = o.window;
    if (!o.headless && display) o.window = true;
    if (o.window && (!glfwInit() || !glfwVulkanSupported())) {
        if (asked) return std::fprintf(stderr, "embed-vk: no display for --window\n"), 2;
        o.window = false;  // a display that does not answer: off screen instead
    }
    if (o.window) {
        uint32_t n = 0;
        const char** required = glfwGetRequiredInstanceExtensions(&n);
        extensions.assign(required, required + n);
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        window = glfwCreateWindow(o.width, o.height, "flarekit embed-vk", nullptr, nullptr);
        if (!window) return std::fprintf(stderr, "embed-vk: no window\n"), 1;
    }
#else
    if (o.window) return std::fprintf(stderr, "embed-vk: built without GLFW\n"), 2;
#endif
    Gpu g(o.validate, extensions);
    VkSurfaceKHR surface = VK_NULL_HANDLE;
#if EMBED_HAS_GLFW
    if (window) check(glfwCreateWindowSurface(g.instance, window, nullptr, &surface), "no surface");
#endif
    g.open(surface);
    const int w = o.width, h = o.height;
    constexpr int kFramesInFlight = 2;
    constexpr VkSampleCountFlagBits kMsaa = VK_SAMPLE_COUNT_4_BIT;
    constexpr VkFormat kHdr = VK_FORMAT_R16G16B16A16_SFLOAT, kDepth = VK_FORMAT_D32_SFLOAT,
                       kLdr = VK_FORMAT_R8G8B8A8_UNORM;

    // The city, as embed-gl draws it.
    const City city = makeCity();
    std::vector<Vertex> mesh;
    for (const CityBox& b : city.boxes) pushBox(mesh, b);
    pushBox(mesh, {{-2000, -1, -2000}, {2000, 0, 2000}, {0.25f, 0.25f, 0.27f}});  // the ground
    for (const Lamp& l : city.lamps) pushBulb(mesh, l);
    Buffer vertices =
        hostBuffer(g, mesh.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    std::memcpy(vertices.mapped, mesh.data(), mesh.size() * sizeof(Vertex));

    // Targets: 4x MSAA colour and depth, the resolved HDR colour flarekit adds flares to, and
    // the tone-mapped 8-bit frame.
    Target msColor = makeTarget(g, kHdr, w, h, kMsaa, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                VK_IMAGE_ASPECT_COLOR_BIT);
    Target msDepth =
        makeTarget(g, kDepth, w, h, kMsaa,
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                   VK_IMAGE_ASPECT_DEPTH_BIT);
    Target hdr = makeTarget(g, kHdr, w, h, VK_SAMPLE_COUNT_1_BIT,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT);
    Target ldr = makeTarget(g, kLdr, w, h, VK_SAMPLE_COUNT_1_BIT,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT);
    Buffer readback = hostBuffer(g, VkDeviceSize(w) * h * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    // With a window: a swapchain the tone-mapped frame is blitted to and presented from.
    const Swapchain swapchain = makeSwapchain(g, surface, w, h);
    if (surface)
        std::printf("embed-vk: a %dx%d window (GLFW, %zu swapchain images)\n", w, h,
                    swapchain.images.size());
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    std::vector<VkSemaphore> acquired(2), presentable(swapchain.images.size());
    for (VkSemaphore& sem : acquired)
        check(vkCreateSemaphore(g.device, &semaphoreInfo, nullptr, &sem), "semaphore");
    for (VkSemaphore& sem : presentable)
        check(vkCreateSemaphore(g.device, &semaphoreInfo, nullptr, &sem), "semaphore");

    // Pipelines: the sky and the city into the MSAA targets, the tone map into the 8-bit frame.
    const Passes passes = makePasses(g, hdr.view, kHdr, kDepth, kMsaa, kLdr);

    // flarekit on the application's device: the sun and every lamp.
    fk_vulkan_device device{};
    device.instance = g.instance;
    device.physical_device = g.physical;
    device.device = g.device;
    device.queue_family_index = g.family;
    device.get_instance_proc_addr = &vkGetInstanceProcAddr;
    device.frames_in_flight = kFramesInFlight;
    fk_engine* flares = fk_engine_create_vulkan(&device, int(city.lamps.size()) + 1);
    if (!flares) return std::fprintf(stderr, "embed-vk: %s\n", fk_error(nullptr)), 1;
    const int sunPreset = fk_engine_load_preset(flares, "tanczos-classic");
    const int lampPreset = fk_engine_load_preset(flares, "subtle");
    if (sunPreset < 0 || lampPreset < 0)
        return std::fprintf(stderr, "embed-vk: %s\n", fk_error(flares)), 1;
    const V3 sun = sunToward(city);
    const std::vector<fk_light> lights = cityLights(city, sunPreset, lampPreset);

    // Frames in flight: a command buffer and a fence each.
    VkCommandPoolCreateInfo commandPoolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    commandPoolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    commandPoolInfo.queueFamilyIndex = g.family;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(g.device, &commandPoolInfo, nullptr, &commandPool), "command pool");
    std::array<VkCommandBuffer, kFramesInFlight> commands{};
    VkCommandBufferAllocateInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cmdInfo.commandPool = commandPool;
    cmdInfo.commandBufferCount = kFramesInFlight;
    check(vkAllocateCommandBuffers(g.device, &cmdInfo, commands.data()), "command buffers");
    std::array<VkFence, kFramesInFlight> fences{};
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    for (VkFence& f : fences) check(vkCreateFence(g.device, &fenceInfo, nullptr, &f), "fence");

    // The targets are reused by consecutive frames; one queue orders them (and the barriers
    // below make each frame's writes wait for the last frame's reads).
    City view = city;
    int frames = 0;
    for (int frame = 0; frame < o.frames || (swapchain.chain && !o.framesGiven); ++frame) {
#if EMBED_HAS_GLFW
        if (window) {
            glfwPollEvents();
            if (glfwWindowShouldClose(window)) break;
        }
#endif
        const int slot = frame % kFramesInFlight;
        // Frame N may reuse what frame N - kFramesInFlight used: wait for it (flarekit's
        // frames_in_flight contract).
        vkWaitForFences(g.device, 1, &fences[slot], VK_TRUE, UINT64_MAX);
        vkResetFences(g.device, 1, &fences[slot]);
        uint32_t image = 0;
        if (swapchain.chain)
            check(vkAcquireNextImageKHR(g.device, swapchain.chain, UINT64_MAX,
                                        acquired[size_t(slot)], VK_NULL_HANDLE, &image),
                  "vkAcquireNextImageKHR");
        VkCommandBuffer cmd = commands[slot];
        vkResetCommandBuffer(cmd, 0);
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(cmd, &begin);

        view.eye.z = city.eye.z - 0.15f * float(frame);  // walking down the street
        const Mat v = lookAt(view.eye, view.target);
        const Mat p =
            reversedInfinitePerspective(view.fovYDeg, float(w) / float(h), view.nearPlane);
        const Mat vp = multiply(p, v);
        const VkPipelineStageFlags everything = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
        transition(cmd, msColor.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, everything, 0,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        transition(cmd, hdr.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, everything, 0,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        transition(cmd, msDepth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, everything, 0,
                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
        VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color.imageView = msColor.view;
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        color.resolveImageView = hdr.view;
        color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // the sky covers every pixel
        color.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = msDepth.view;
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;  // flarekit reads it
        depth.clearValue.depthStencil = {0.f, 0};      // reversed Z: infinity
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, {uint32_t(w), uint32_t(h)}};
        rendering.layerCount = 1;
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachments = &color;
        rendering.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &rendering);
        const VkViewport viewport{0, 0, float(w), float(h), 0, 1};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
        const float tanHalfY = std::tan(view.fovYDeg * 3.14159265f / 360.f);
        const float sky[20] = {v[0],
                               v[4],
                               v[8],
                               0,
                               v[1],
                               v[5],
                               v[9],
                               0,
                               -v[2],
                               -v[6],
                               -v[10],
                               0,
                               sun.x,
                               sun.y,
                               sun.z,
                               std::cos(city.sunRadiusDeg * 3.14159265f / 180.f),
                               tanHalfY * float(w) / float(h),
                               tanHalfY,
                               0,
                               0};
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, passes.sky);
        vkCmdPushConstants(cmd, passes.sceneLayout, passes.push.stageFlags, 0, sizeof sky, sky);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        float camera[20];
        std::memcpy(camera, vp.data(), 64);
        camera[16] = sun.x, camera[17] = sun.y, camera[18] = sun.z, camera[19] = 0;
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, passes.scene);
        vkCmdPushConstants(cmd, passes.sceneLayout, passes.push.stageFlags, 0, sizeof camera,
                           camera);
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertices.buffer, &offset);
        vkCmdDraw(cmd, uint32_t(mesh.size()), 1, 0, 0);
        vkCmdEndRendering(cmd);

        // flarekit: its depth read by a compute pass, its flares added to the resolved colour.
        transition(cmd, msDepth.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                   VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
        transition(
            cmd, hdr.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        fk_frame f{};
        f.width = w, f.height = h;
        f.viewport[2] = w, f.viewport[3] = h;
        f.depth_convention = FK_DEPTH_REVERSED_Z;
        std::memcpy(f.view, v.data(), sizeof f.view);
        std::memcpy(f.projection, p.data(), sizeof f.projection);
        f.dt_seconds = 1.f / 60.f;
        fk_vulkan_frame vf{};
        vf.command_buffer = cmd;
        vf.frame_index = uint64_t(frame);
        vf.depth_view = msDepth.view;
        vf.depth_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
        vf.depth_samples = kMsaa;
        vf.color_view = hdr.view;
        vf.color_format = kHdr;
        vf.color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        if (fk_engine_record_occlusion(flares, &vf, &f, lights.data(), int(lights.size())) < 0 ||
            fk_engine_record_draw(flares, &vf, &f, lights.data(), int(lights.size())) < 0)
            return std::fprintf(stderr, "embed-vk: %s\n", fk_error(flares)), 1;

        // The application's tone map.
        transition(
            cmd, hdr.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            VK_ACCESS_SHADER_READ_BIT);
        transition(cmd, ldr.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, everything, 0,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
        VkRenderingAttachmentInfo out{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        out.imageView = ldr.view;
        out.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        out.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        out.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        VkRenderingInfo toneRendering = rendering;
        toneRendering.pColorAttachments = &out;
        toneRendering.pDepthAttachment = nullptr;
        vkCmdBeginRendering(cmd, &toneRendering);
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, passes.tonemap);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, passes.tonemapLayout, 0, 1,
                                &passes.hdrSet, 0, nullptr);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
        transition(cmd, ldr.image, VK_IMAGE_ASPECT_COLOR_BIT,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_ACCESS_TRANSFER_READ_BIT);
        if (swapchain.chain) {  // the frame to the window
            const VkImage target = swapchain.images[image];
            transition(cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
            VkImageBlit blit{};
            blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            blit.srcOffsets[1] = {w, h, 1};
            blit.dstOffsets[1] = {int32_t(swapchain.extent.width), int32_t(swapchain.extent.height),
                                  1};
            vkCmdBlitImage(cmd, ldr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
            transition(cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
        }
        {  // every frame to the host buffer (a window may close any time); the last is written
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {uint32_t(w), uint32_t(h), 1};
            vkCmdCopyImageToBuffer(cmd, ldr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   readback.buffer, 1, &region);
            VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                                 1, &host, 0, nullptr, 0, nullptr);
        }
        check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        const VkPipelineStageFlags waitAt = VK_PIPELINE_STAGE_TRANSFER_BIT;
        if (swapchain.chain) {
            submit.waitSemaphoreCount = 1;
            submit.pWaitSemaphores = &acquired[size_t(slot)];
            submit.pWaitDstStageMask = &waitAt;
            submit.signalSemaphoreCount = 1;
            submit.pSignalSemaphores = &presentable[image];
        }
        check(vkQueueSubmit(g.queue, 1, &submit, fences[slot]), "vkQueueSubmit");
        if (swapchain.chain) {
            VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
            present.waitSemaphoreCount = 1;
            present.pWaitSemaphores = &presentable[image];
            present.swapchainCount = 1;
            present.pSwapchains = &swapchain.chain;
            present.pImageIndices = &image;
            check(vkQueuePresentKHR(g.queue, &present), "vkQueuePresentKHR");
        }
        frames = frame + 1;
    }
    vkDeviceWaitIdle(g.device);

    std::vector<float> coverage(lights.size());
    const int n = fk_engine_read_coverage(flares, coverage.data(), int(coverage.size()));
    int seen = 0;
    for (int i = 0; i < n; ++i) seen += coverage[size_t(i)] > 0.f ? 1 : 0;
    std::ofstream ppm(o.out, std::ios::binary);
    ppm << "P6\n" << w << " " << h << "\n255\n";
    const auto* rgba = static_cast<const unsigned char*>(readback.mapped);
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i)
        ppm.write(reinterpret_cast<const char*>(rgba + 4 * i), 3);
    if (!ppm.flush()) return std::fprintf(stderr, "embed-vk: cannot write %s\n", o.out.c_str()), 1;
    std::printf("embed-vk: %d frames %dx%d, %zu lights (%d seen), last frame in %s\n", frames, w, h,
                lights.size(), seen, o.out.c_str());
    if (!o.sceneJson.empty() && !writeSceneJson(view, w, h, o.sceneJson)) return 1;
    if (!o.coverageJson.empty()) {
        std::ofstream c(o.coverageJson);
        c << "{\"coverage\": [";
        for (int i = 0; i < n; ++i) c << (i ? ", " : "") << coverage[size_t(i)];
        c << "]}\n";
        if (!c.flush()) return 1;
    }

    fk_engine_destroy(flares);
    for (VkFence f : fences) vkDestroyFence(g.device, f, nullptr);
    vkDestroyCommandPool(g.device, commandPool, nullptr);
    destroy(g, passes);
    for (Target* t : {&msColor, &msDepth, &hdr, &ldr}) destroy(g, *t);
    destroy(g, vertices);
    destroy(g, readback);
    for (VkSemaphore sem : acquired) vkDestroySemaphore(g.device, sem, nullptr);
    for (VkSemaphore sem : presentable) vkDestroySemaphore(g.device, sem, nullptr);
    if (swapchain.chain) vkDestroySwapchainKHR(g.device, swapchain.chain, nullptr);
    if (surface) vkDestroySurfaceKHR(g.instance, surface, nullptr);
#if EMBED_HAS_GLFW
    if (window) glfwDestroyWindow(window), glfwTerminate();
#endif
    if (o.validate && g_validationMessages > 0) {
        std::fprintf(stderr, "embed-vk: %d validation messages\n", g_validationMessages);
        return 1;
    }
    return 0;
}
