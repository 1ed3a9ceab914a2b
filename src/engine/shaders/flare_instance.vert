#version 450
// SPDX-License-Identifier: Apache-2.0
// The any-renderer flare draw: one quad per fk_flare_instance record (fk_flare_set_instances),
// four vertices a triangle strip, instanced over the records of one sprite slot. One source
// for every renderer: GLSL 4.50 as is for OpenGL, compiled to SPIR-V for Vulkan (glslc defines
// VULKAN), and from that SPIR-V to HLSL and MSL by SPIRV-Cross. Bindings (set 0 in Vulkan;
// docs/engine-api.md lists each language's): 0 the records, 1 the frame block, 2 the sprite.
#ifdef VULKAN
#define BINDING(n) set = 0, binding = n
#define VERTEX_INDEX gl_VertexIndex
#define INSTANCE_INDEX gl_InstanceIndex
#else
#define BINDING(n) binding = n
#define VERTEX_INDEX gl_VertexID
#define INSTANCE_INDEX gl_InstanceID
#endif

struct Instance {
    vec4 positionHalfSize;  // xy: centre, viewport pixels from the bottom-left; zw: half size
    vec4 rotationColor;     // x: rotation, radians counter-clockwise; yzw: linear RGB factor
    ivec4 slotLight;        // x: sprite slot, y: light, z: preset, w: element
};
layout(std430, BINDING(0)) readonly buffer Instances { Instance records[]; } instances;
layout(std140, BINDING(1)) uniform Frame {
    vec2 viewportSize;  // pixels
    float clipYSign;    // 1 where clip-space y points up (GL, Direct3D, Metal), -1 for Vulkan
    int firstInstance;  // the slot's first record: draw with base instance 0 and set this
} frame;

layout(location = 0) out vec2 uv;
layout(location = 1) flat out vec3 tint;

void main() {
    Instance r = instances.records[frame.firstInstance + INSTANCE_INDEX];
    vec2 corner = vec2(VERTEX_INDEX & 1, (VERTEX_INDEX >> 1) & 1);
    uv = vec2(corner.x, 1.0 - corner.y);  // sprites are stored top row first
    tint = r.rotationColor.yzw;
    vec2 local = (corner * 2.0 - 1.0) * r.positionHalfSize.zw;
    float c = cos(r.rotationColor.x), s = sin(r.rotationColor.x);
    vec2 p = r.positionHalfSize.xy + vec2(c * local.x - s * local.y, s * local.x + c * local.y);
    vec2 ndc = p / frame.viewportSize * 2.0 - 1.0;
    gl_Position = vec4(ndc.x, ndc.y * frame.clipYSign, 0.0, 1.0);
}
