// SPDX-License-Identifier: Apache-2.0
// A headless Vulkan application for flarekit's own use: the CLI's `--backend vulkan` and the
// tests create one to give the engine API a device, as an application would (instance,
// device with Vulkan 1.3's dynamic rendering, one graphics-and-compute queue, a command pool),
// render a scene's depth into their own images and read images back. With validation on, the
// Khronos validation layer checks every call and the host counts what it reports.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/vulkan/VulkanResources.h"
#include "flarekit/Result.h"
#include "flarekit/Scene.h"
#include "flarekit/flarekit_vulkan.h"

namespace flarekit::vk {

//! A depth image of the host's, with its view (depth aspect) and format.
struct DepthImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_D32_SFLOAT;
    int samples = 1;
    int width = 0, height = 0;
};

class VulkanHost;

//! A scene's objects as the Vulkan occluder callback draws them into sun-map tiles (as
//! SceneOccluders does on GL): opaque ones black, translucent ones multiplying the tile by
//! 1 - opacity, closed ones by their front faces. The host must outlive it.
class VulkanOccluders {
  public:
    static Result<std::unique_ptr<VulkanOccluders>> create(const VulkanHost& host,
                                                           const Scene& scene);
    ~VulkanOccluders();
    //! The callback (fk_vulkan_occluder_callback); `user` is the VulkanOccluders.
    static void draw(void* user, VkCommandBuffer cmd, int view, int light,
                     const float viewProjection[16]);
    int calls = 0;  //!< how many tiles it drew

  private:
    struct Impl;
    explicit VulkanOccluders(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

class VulkanHost {
  public:
    //! `validation`: enable VK_LAYER_KHRONOS_validation and count its messages (an error if
    //! the layer is not installed).
    static Result<std::unique_ptr<VulkanHost>> create(bool validation);
    ~VulkanHost();

    //! The device for fk_engine_create_vulkan.
    fk_vulkan_device engineDevice(int framesInFlight) const;
    const Device& device() const { return *m_device; }
    //! Records with `record` into a fresh command buffer, submits it and waits.
    Status submit(const std::function<void(VkCommandBuffer)>& record);
    //! As submit, with timestamps before and after `record`'s commands: their GPU time in ms.
    Result<double> submitTimed(const std::function<void(VkCommandBuffer)>& record);
    //! A colour image (RGBA16F or RGBA32F) in COLOR_ATTACHMENT_OPTIMAL usable as attachment,
    //! transfer source and destination, holding `rgba` (width x height x 4 floats, rows from the
    //! top; null: zero).
    Result<Image> colorImage(VkFormat format, int width, int height, const float* rgba);
    //! A sampled RGBA16F image in SHADER_READ_ONLY_OPTIMAL holding `rgba` (rows from the top),
    //! visible to compute shaders: the application's transmittance, say.
    Result<Image> sampledImage(int width, int height, const float* rgba);
    //! Its pixels read back (R32G32B32A32_SFLOAT images), rows from the top.
    Result<std::vector<float>> readColor(const Image& image, int width, int height);
    Result<DepthImage> depthImage(int width, int height, int samples, VkFormat format);
    void destroy(DepthImage& d) const;
    //! Draws `mesh` (triangle positions, xyz each) with `viewProjection` (column-major) into
    //! `depth` under `convention` (cleared to the far value, compared LESS, or GREATER for
    //! reversed Z; [-1, 1] clip z through VK_EXT_depth_clip_control), and leaves it in
    //! DEPTH_STENCIL_READ_ONLY_OPTIMAL, its writes visible to compute shaders.
    Status drawDepth(const DepthImage& depth, const std::vector<float>& mesh,
                     const float viewProjection[16], fk_depth_convention convention);

    //! Validation messages of warning or error severity so far, and the first one's text.
    int validationMessages() const;
    std::string firstValidationMessage() const;
    std::string deviceName() const;

  private:
    friend class VulkanOccluders;
    //! An RGBA16F or RGBA32F image holding `rgba` (zero if null), left in `layout` for
    //! `stage`'s `access`.
    Result<Image> upload(VkFormat format, int width, int height, const float* rgba,
                         VkImageUsageFlags usage, VkImageLayout layout, VkPipelineStageFlags stage,
                         VkAccessFlags access);
    struct Impl;
    explicit VulkanHost(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
    const Device* m_device = nullptr;
};

}  // namespace flarekit::vk
