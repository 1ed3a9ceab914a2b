// SPDX-License-Identifier: Apache-2.0
/* flarekit's embedding API: lens flares for any OpenGL renderer, measured on the application's
 * own depth buffer (flarekit_vulkan.h: the same engine on a Vulkan device; fk_flare_set below:
 * instance data and shaders for any other renderer). A C ABI, so C#, Rust, Python ctypes and engine
 * plug-ins can call it; flarekit/flarekit.hpp wraps it in a C++ class. Every call needs a current
 * OpenGL 4.5 core context (the application's own) and leaves the application's GL state as it found
 * it.
 *
 * A frame: fk_engine_occlusion measures every light's coverage (the visible share of its disc
 * or sphere, uniform over solid angle, as `flarekit visibility --method raycast` defines it) in
 * one batched compute dispatch per view, smooths it per light on the GPU, and fk_engine_draw
 * adds every light's sprite flare, instanced and additive, in linear HDR, into the
 * application's framebuffer before its tone map. Nothing is read back in the frame loop.
 * Errors: calls return < 0 (or NULL) and fk_error says which argument was wrong and what was
 * expected; nothing is drawn and no GL error is left. A call that needs GL without a current
 * context returns an error too. See docs/engine-api.md. */
#ifndef FLAREKIT_FLAREKIT_H
#define FLAREKIT_FLAREKIT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define FK_API __declspec(dllimport)
#elif defined(__GNUC__)
#define FK_API __attribute__((visibility("default")))
#else
#define FK_API
#endif

/* What a failed call returns (fk_error has the one-line reason). */
#define FK_ERROR_INVALID (-1)     /* a refused argument or file: the caller's data */
#define FK_ERROR_INTERNAL (-2)    /* a failure inside flarekit or the GL driver */
#define FK_ERROR_INTERRUPTED (-3) /* stopped by SIGINT/SIGTERM at a safe point */

#define FK_VERSION_MAJOR 0
#define FK_VERSION_MINOR 2
/* Views (eyes, multiview layers) one engine measures: rows of fk_engine_coverage_texture. */
#define FK_MAX_VIEWS 4
/* Largest max_lights: the coverage texture is max_lights texels wide, and 16384 is the texture
 * width every GL 4.5 implementation we know of allows (GL_MAX_TEXTURE_SIZE). */
#define FK_MAX_LIGHTS 16384

typedef struct fk_engine fk_engine;

/* How the stored depth relates to `projection`. MINUS_ONE_TO_ONE: classic OpenGL, stored
 * depth = (z_ndc + 1) / 2. ZERO_TO_ONE: glClipControl(..., GL_ZERO_TO_ONE), stored depth =
 * z_ndc. REVERSED_Z: ZERO_TO_ONE with a projection that maps near to 1 and far (or infinity)
 * to 0. A light is unoccluded along a ray where the stored depth is at or beyond the light's
 * own depth (a point light behind a far wall stays hidden; one in front of it stays visible). */
typedef enum {
    FK_DEPTH_MINUS_ONE_TO_ONE = 0,
    FK_DEPTH_ZERO_TO_ONE = 1,
    FK_DEPTH_REVERSED_Z = 2
} fk_depth_convention;

typedef struct {
    unsigned
        depth_texture; /* GL name: GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE, any depth format */
    int width, height; /* size of that texture */
    int viewport[4];   /* x, y, w, h of the view inside it, GL convention (origin bottom-left) */
    fk_depth_convention depth_convention;
    float view[16]; /* column-major, as glUniformMatrix4fv(..., GL_FALSE, ...) */
    float projection[16];
    float dt_seconds; /* time since the previous frame of this view, for the temporal filter */
} fk_frame;

typedef enum { FK_LIGHT_DIRECTIONAL = 0, FK_LIGHT_POINT = 1 } fk_light_type;

typedef struct {
    fk_light_type type;
    float position[3];  /* point lights: world position */
    float direction[3]; /* directional lights: from the camera toward the light */
    float radius; /* point: sphere radius, world units; directional: angular radius, degrees */
    float color[3];
    float intensity;
    int preset; /* id from fk_engine_load_preset; -1 draws no flare for this light */
} fk_light;

/* An engine for up to max_lights lights per call (1..FK_MAX_LIGHTS). NULL on failure;
 * fk_error(NULL) says why. It clears GL errors left pending before it (glGetError), so that
 * it can tell its own; no other call reads or clears GL errors. */
FK_API fk_engine* fk_engine_create(int max_lights);
/* With the engine's context current; without one the engine's GL objects are left to the
 * context's destruction. */
FK_API void fk_engine_destroy(fk_engine* e);
/* The last error, "" if none. fk_error(NULL): the last failed fk_engine_create. */
FK_API const char* fk_error(const fk_engine* e);

/* A sprite preset by shipped name ("tanczos-classic", `flarekit presets`) or JSON path.
 * >= 0 id, < 0 error. */
FK_API int fk_engine_load_preset(fk_engine* e, const char* name_or_path);
/* A visibility method name: "compute" (default: the frame's depth, one batched pass) or
 * "texture-mask" (GPG2's sun maps, drawn by the occluder callback: lights off screen keep
 * their coverage, and grey occluders give translucency exactly). */
FK_API int fk_engine_set_method(fk_engine* e, const char* method);

/* Measures every light in `frame`'s depth: one dispatch, 0 ok, < 0 error. */
FK_API int fk_engine_occlusion(fk_engine* e, const fk_frame* frame, const fk_light* lights,
                               int count);
/* Stereo / multiview: one frame per view (1..FK_MAX_VIEWS), each with its own coverage. */
FK_API int fk_engine_occlusion_views(fk_engine* e, const fk_frame* frames, int views,
                                     const fk_light* lights, int count);
/* R32F, max_lights x FK_MAX_VIEWS: filtered coverage of light i in view v at texel (i, v), on
 * the GPU, for the application's own shaders (texelFetch). */
FK_API unsigned fk_engine_coverage_texture(const fk_engine* e);
/* Raw coverage of the last occlusion call, view 0 (waits for the GPU); for tests and tools.
 * Returns the number of values written (min(count, lights of that call)) or < 0. */
FK_API int fk_engine_read_coverage(fk_engine* e, float* out, int count);

/* Adds every light's flare for view 0 of the last occlusion call into `framebuffer` (0: the
 * default one) inside frame->viewport: instanced, additive, each light scaled by its filtered
 * coverage, its edge fade and its flux (intensity x colour over its disc on screen). */
FK_API int fk_engine_draw(fk_engine* e, const fk_frame* frame, const fk_light* lights, int count,
                          unsigned framebuffer);

/* ---- Added beyond the first contract ---- */

/* The library's version: major x 10000 + minor x 100 (0.2: 200). */
FK_API int fk_version(void);

/* Raw coverage / in-frame share / filtered coverage of view `view` (waits for the GPU). */
FK_API int fk_engine_read_view(fk_engine* e, int view, float* coverage, float* in_frame,
                               float* filtered, int count);
/* As fk_engine_draw, with view `view`'s coverage (the right eye of a stereo pair: 1). */
FK_API int fk_engine_draw_view(fk_engine* e, int view, const fk_frame* frame,
                               const fk_light* lights, int count, unsigned framebuffer);
/* Translucency: a GL_TEXTURE_2D whose red channel is the share of light that gets through each
 * pixel of view `view` (the application's foliage alpha, glass, fog cards); it multiplies every
 * visible depth sample, sampled over the depth texture's extent. 0 removes it. */
FK_API int fk_engine_set_transmittance(fk_engine* e, int view, unsigned texture);
/* texture-mask: the engine binds `framebuffer`, sets the viewport to `viewport` (light `light`'s
 * tile of the sun-map atlas, cleared to white) and calls this once per light and view. Draw
 * every occluder there with `view_projection` (column-major, in the clip space of the frame's
 * depth convention) in black, with depth testing off; a translucent one may multiply the tile
 * by 1 - opacity instead (glBlendFunc(GL_ZERO, GL_SRC_COLOR); closed objects front faces
 * only). The camera sits at the eye, looks along the light and sees exactly its cone; for a
 * point light its far plane stops before the light, so what is behind the light is clipped.
 * Leave the framebuffer bound; any other state may change (the call restores the caller's). */
typedef void (*fk_occluder_callback)(void* user, int view, int light,
                                     const float view_projection[16], unsigned framebuffer,
                                     const int viewport[4]);
FK_API int fk_engine_set_occluder_callback(fk_engine* e, fk_occluder_callback callback, void* user);
/* Off-screen lights: the application rendered view `view`'s depth past its viewport (a guard
 * band: the whole depth texture, with the frame's projection extended over it), so directions
 * that fall outside the viewport but inside the texture are measured instead of counted as
 * unseen. A light just outside the frame then keeps its coverage, and its edge-streak elements
 * stay lit as it leaves. in_frame still counts the viewport only. Off (0) by default. */
FK_API int fk_engine_set_guard_band(fk_engine* e, int view, int enabled);
/* Directions sampled per light: samples_per_side^2 (1..64; default 32, 1,024 rays per light,
 * a standard error near 0.004 on an edge across the disc). */
FK_API int fk_engine_set_samples(fk_engine* e, int samples_per_side);
/* Small lights with method "compute": a light whose disc covers fewer than `depth_samples`
 * samples of the frame's depth (pi r^2 x the MSAA count, r its radius in pixels) is measured
 * from a sun-map tile the occluder callback draws, as "texture-mask" measures every light, in
 * the same call; the others on the depth. A depth buffer places an edge only to its sample
 * grid, a large share of a disc a few pixels wide. Default 1,024 (a radius under 18 px at 1x,
 * 9 px at 4x MSAA); 0 measures every light on the depth. Without an occluder callback every
 * light is measured on the depth. Cost: one callback per small light and view. */
FK_API int fk_engine_set_tile_threshold(fk_engine* e, int depth_samples);
/* The temporal filter (flarekit/Temporal.h): attack and release time constants in seconds
 * (defaults 0.04, 0.12) and the edge-fade width in shorter sides of the viewport (0.08). */
FK_API int fk_engine_set_temporal(fk_engine* e, float attack_seconds, float release_seconds,
                                  float guard_band);
/* Forgets the filtered coverage: the next call starts each light from its measurement. */
FK_API int fk_engine_reset(fk_engine* e);
/* A preset from JSON text in memory (`length` bytes, no terminator needed), for engines whose
 * assets are packed: the same format and checks as a preset file. >= 0 id, < 0 error. */
FK_API int fk_engine_load_preset_json(fk_engine* e, const char* json, size_t length);

/* ---- Any renderer: flares as instance data (no GL; any thread, one set per thread) ----
 * For Direct3D, Metal, WebGPU, Vulkan and engines with their own pipelines: an fk_flare_set
 * holds presets and their sprite textures for one frame height; fk_flare_set_instances turns
 * lights and their coverage (the engine's own occlusion query, its own texture read, or
 * fk_engine_read_view) into one record per element per light, which the shaders of
 * fk_flare_shader draw: a quad per record, premultiplied sprite x colour, added to the linear
 * HDR colour (blend rgb ONE, ONE; alpha ZERO, ONE). See docs/engine-api.md for the bindings. */
typedef struct fk_flare_set fk_flare_set;

typedef struct {
    float position[2];  /* the quad's centre, viewport pixels, origin bottom-left (as GL) */
    float half_size[2]; /* half width and height in pixels, before rotation */
    float rotation;     /* radians, counter-clockwise: 0, or pi/2 for an edge streak on a side
                           edge (its sprite is symmetric, so the turn's direction is free) */
    float color[3];     /* linear RGB factor of the sprite's premultiplied rgb (alpha is not) */
    int texture;        /* sprite slot: fk_flare_set_texture */
    int light;          /* the light's index in the call */
    int preset;         /* the light's preset id */
    int element;        /* the element's index among its preset's sprites */
} fk_flare_instance;

FK_API fk_flare_set* fk_flare_set_create(void);
FK_API void fk_flare_set_destroy(fk_flare_set* s);
/* The set's last error, "" if none (fk_flare_set_error(NULL): the last failed create). */
FK_API const char* fk_flare_set_error(const fk_flare_set* s);
/* As fk_engine_load_preset / fk_engine_load_preset_json: >= 0 id, < 0 error. */
FK_API int fk_flare_set_load_preset(fk_flare_set* s, const char* name_or_path);
FK_API int fk_flare_set_load_preset_json(fk_flare_set* s, const char* json, size_t length);
/* Renders every loaded preset's sprites for frames `frame_height` pixels tall (element sizes
 * are fractions of the height). Returns the number of sprite slots, over all presets, or < 0.
 * Call again after loading a preset or when the viewport's height changes. */
FK_API int fk_flare_set_prepare(fk_flare_set* s, int frame_height);
/* Sprite slot `slot`: its size, and with `rgba` non-NULL its texels (width x height x 4
 * floats, premultiplied linear RGBA, top row first, a clear border around the element).
 * Upload as a texture sampled linearly with clamping. 0 ok, < 0 error. */
FK_API int fk_flare_set_texture(const fk_flare_set* s, int slot, int* width, int* height,
                                float* rgba);
/* The instances of `count` lights (presets from this set) seen through `frame` (its matrices
 * and viewport; the depth texture is not read), each light weighed by coverage[i] in [0, 1],
 * faded near the viewport's edge over `edge_fade` shorter sides (0.08: the engine's default)
 * and by its flux, as fk_engine_draw weighs it. Writes at most `capacity` records in draw
 * order (preset, element, light) and returns how many there are (out may be NULL to count
 * them), or < 0. The frame's viewport height must be the prepared height. */
FK_API int fk_flare_set_instances(fk_flare_set* s, const fk_frame* frame, const fk_light* lights,
                                  const float* coverage, int count, float edge_fade,
                                  fk_flare_instance* out, int capacity);

/* The shaders that draw fk_flare_instance records, compiled at build time from one GLSL
 * source: GLSL 4.50 for OpenGL, SPIR-V for Vulkan, HLSL (shader model 5.0) for Direct3D
 * 11/12, MSL 2.0 for Metal. Returns the text (NUL-terminated; SPIR-V: the binary) and its
 * size in bytes, or NULL for an unknown language or stage. */
typedef enum {
    FK_SHADER_GLSL = 0,
    FK_SHADER_SPIRV = 1,
    FK_SHADER_HLSL = 2,
    FK_SHADER_MSL = 3
} fk_shader_language;
typedef enum { FK_SHADER_VERTEX = 0, FK_SHADER_FRAGMENT = 1 } fk_shader_stage;
FK_API const void* fk_flare_shader(fk_shader_language language, fk_shader_stage stage,
                                   size_t* size);

#ifdef __cplusplus
}
#endif

#endif /* FLAREKIT_FLAREKIT_H */
