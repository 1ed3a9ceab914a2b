// SPDX-License-Identifier: Apache-2.0
/* flarekit's embedding API on Vulkan: the engine of flarekit.h created on the application's own
 * Vulkan device, recording its occlusion pass and its flares into command buffers the
 * application owns and submits. Include this instead of flarekit.h; it includes
 * <vulkan/vulkan.h> (define VK_NO_PROTOTYPES before it if your loader is volk or your own).
 *
 * The settings calls of flarekit.h work on a Vulkan engine too (fk_engine_load_preset,
 * fk_engine_load_preset_json, fk_engine_set_samples, fk_engine_set_temporal,
 * fk_engine_set_guard_band, fk_engine_set_tile_threshold, fk_engine_reset,
 * fk_engine_read_view, fk_error); the GL calls (fk_engine_occlusion, fk_engine_draw, textures,
 * the GL occluder callback) return an error on it.
 *
 * Synchronisation, which the docs (docs/engine-api.md, "Vulkan") state in full:
 * - Before fk_engine_record_occlusion's commands the depth image must be in depth_layout with
 *   its writes visible to compute-shader reads (the application's barrier, as for any
 *   sampling of a depth attachment); the transmittance image likewise, if any.
 * - Before fk_engine_record_draw's commands the colour image must be in color_layout
 *   (COLOR_ATTACHMENT_OPTIMAL or GENERAL) with its writes visible to colour-attachment reads;
 *   the calls leave it in that layout, its flares written by COLOR_ATTACHMENT_OUTPUT.
 * - Everything else (the engine's own buffers and images) the engine's recorded barriers
 *   order, on one queue of queue_family_index, in submission order.
 * - Frames in flight: frame_index counts the application's frames. Recording frame N, the
 *   application has waited for the GPU to finish frame N - frames_in_flight (the usual fence
 *   per frame in flight); the engine reuses that frame's descriptor sets and frees what it
 *   retired then.
 * - One thread at a time per engine; command buffers of one engine are submitted in the order
 *   they were recorded. fk_engine_read_view reads what the last finished frame measured.
 */
#ifndef FLAREKIT_FLAREKIT_VULKAN_H
#define FLAREKIT_FLAREKIT_VULKAN_H

#include <vulkan/vulkan.h>

#include "flarekit.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    VkInstance instance;
    VkPhysicalDevice physical_device;
    /* Created with Vulkan 1.3's dynamicRendering feature on (or VK_KHR_dynamic_rendering). */
    VkDevice device;
    uint32_t queue_family_index;            /* graphics and compute */
    const VkAllocationCallbacks* allocator; /* NULL: the driver's */
    /* NULL: vkGetInstanceProcAddr of the system's loader (libvulkan.so.1). */
    PFN_vkGetInstanceProcAddr get_instance_proc_addr;
    int frames_in_flight; /* 1..8 */
} fk_vulkan_device;

/* What a Vulkan frame adds to fk_frame (whose depth_texture is not read; width and height
 * are the depth image's size, and viewport's y is measured from the top, as Vulkan's). */
typedef struct {
    VkCommandBuffer command_buffer; /* recording, outside a render pass */
    uint64_t frame_index;           /* the application's frame counter */
    /* The depth: a 2D view of its depth aspect, any depth format, 1 to 16 samples, created
     * with SAMPLED usage, in depth_layout (DEPTH_STENCIL_READ_ONLY_OPTIMAL,
     * DEPTH_READ_ONLY_OPTIMAL, SHADER_READ_ONLY_OPTIMAL or GENERAL). */
    VkImageView depth_view;
    VkImageLayout depth_layout;
    VkSampleCountFlagBits depth_samples;
    /* Optional translucency (fk_engine_set_transmittance's texture): a single-sample colour
     * view whose red channel is the share of light let through, or VK_NULL_HANDLE. */
    VkImageView transmittance_view;
    VkImageLayout transmittance_layout;
    /* The linear HDR colour the flares are added into (fk_engine_record_draw). */
    VkImageView color_view;
    VkFormat color_format; /* a format with COLOR_ATTACHMENT and BLEND support */
    VkImageLayout color_layout;
} fk_vulkan_frame;

/* An engine for up to max_lights lights per call on the application's device. NULL on
 * failure; fk_error(NULL) says why (a missing function, an unsupported device). */
FK_API fk_engine* fk_engine_create_vulkan(const fk_vulkan_device* device, int max_lights);

/* Records the measurement of every light in frame->depth (one dispatch per view) into
 * vk->command_buffer. 0 ok, < 0 error (nothing recorded). */
FK_API int fk_engine_record_occlusion(fk_engine* e, const fk_vulkan_frame* vk,
                                      const fk_frame* frame, const fk_light* lights, int count);
/* Records every light's flare, weighed by the last recorded occlusion of view 0, added into
 * vk->color_view inside frame->viewport (dynamic rendering: the engine begins and ends its
 * own rendering). 0 ok, < 0 error. */
FK_API int fk_engine_record_draw(fk_engine* e, const fk_vulkan_frame* vk, const fk_frame* frame,
                                 const fk_light* lights, int count);

/* Small lights on Vulkan, as fk_engine_set_occluder_callback on GL: with a callback set, the
 * lights under fk_engine_set_tile_threshold's depth samples are measured from sun maps. Inside
 * fk_engine_record_occlusion the engine begins rendering into its sun-map atlas (dynamic
 * rendering: one colour attachment of FK_VULKAN_SUN_MAP_FORMAT cleared to white, no depth, one
 * sample), and for each such light sets the viewport and scissor to the light's tile and calls
 * this. Bind a pipeline made for that rendering and draw every occluder with
 * `view_projection` (column-major, the frame's depth convention, y up as GL's: the sums are
 * symmetric, so the flip is free) in black, or a translucent one multiplying the tile by
 * 1 - opacity (blend ZERO, SRC_COLOR; closed objects by their front faces). Leave the
 * rendering open; bind what you like (the engine binds its own after). */
#define FK_VULKAN_SUN_MAP_FORMAT VK_FORMAT_R8G8B8A8_UNORM
typedef void (*fk_vulkan_occluder_callback)(void* user, VkCommandBuffer command_buffer, int view,
                                            int light, const float view_projection[16]);
FK_API int fk_engine_set_vulkan_occluder_callback(fk_engine* e,
                                                  fk_vulkan_occluder_callback callback, void* user);

/* The filtered coverage image (R32_SFLOAT, max_lights x FK_MAX_VIEWS, GENERAL layout) for
 * the application's own shaders, as fk_engine_coverage_texture is on GL. */
FK_API VkImageView fk_engine_coverage_view(const fk_engine* e);

#ifdef __cplusplus
}
#endif

#endif /* FLAREKIT_FLAREKIT_VULKAN_H */
