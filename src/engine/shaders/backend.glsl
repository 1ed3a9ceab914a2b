// SPDX-License-Identifier: Apache-2.0
// One shader source for both backends: prepended first to every engine shader. OpenGL builds
// them at run time as they are; the Vulkan backend's SPIR-V is compiled at build time by
// glslc, which defines VULKAN. What differs is said here once:
// - BINDING(gl, vk): a resource's GL binding (texture units, image units and buffer bindings
//   are separate in GL) or its binding in the Vulkan backend's descriptor set 0;
// - UNIFORMS_BEGIN(Name, vk) / UNIFORM / UNIFORMS_END: GL's loose uniforms, which Vulkan keeps
//   in a std140 uniform block at binding vk (src/engine/vulkan/VulkanParams.h lays them out);
// - INSTANCE_ID / VERTEX_ID: the built-ins' names;
// - SPRITE_ROW_FROM_TOP: Vulkan's clip space points y down, so a quad's top corner is drawn
//   at the framebuffer's top and reads the sprite's first (top) row.
#ifdef VULKAN
#define BINDING(gl, vk) set = 0, binding = vk
#define UNIFORMS_BEGIN(Name, vk) layout(std140, set = 0, binding = vk) uniform Name {
#define UNIFORM
#define UNIFORMS_END };
#define INSTANCE_ID gl_InstanceIndex
#define VERTEX_ID gl_VertexIndex
#define SPRITE_ROW_FROM_TOP 1
#else
#define BINDING(gl, vk) binding = gl
#define UNIFORMS_BEGIN(Name, vk)
#define UNIFORM uniform
#define UNIFORMS_END
#define INSTANCE_ID gl_InstanceID
#define VERTEX_ID gl_VertexID
#define SPRITE_ROW_FROM_TOP 0
#endif
