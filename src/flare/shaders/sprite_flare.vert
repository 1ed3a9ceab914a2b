#version 450 core
// SPDX-License-Identifier: Apache-2.0
// One flare element as a quad (triangle strip of 4) on the flare vector. Its brightness is
// read here, in the vertex shader, from the 1x1 weight texture a visibility method or the
// temporal filter wrote: the CPU never reads it. A weight of 0 collapses the quad, as
// renderFlare skips elements with no intensity.
layout(binding = 1) uniform sampler2D flareWeight;
uniform int weightChannel;
uniform float brightnessScale;  // sunFlareScale of the sun (its flux, flarekit/SunFlare.h)
uniform vec2 centre;            // element centre, GL pixels (origin bottom-left)
uniform vec2 halfSize;          // half the quad, pixels
uniform vec2 frameSize;
uniform float elementWeight;  // an edge streak's placement weight (edgeStreakPlacement); else 1
uniform bool transposed;      // an edge streak on a side edge: the sprite turned a quarter
out vec2 uv;
flat out float intensity;
void main() {
    intensity = texelFetch(flareWeight, ivec2(0), 0)[weightChannel] * brightnessScale * elementWeight;
    vec2 corner = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1);
    uv = vec2(corner.x, 1.0 - corner.y);  // element images are stored top row first
    // A quarter turn of a sprite symmetric about both axes is its transpose.
    if (transposed) uv = vec2(corner.y, 1.0 - corner.x);
    vec2 p = centre + (corner * 2.0 - 1.0) * (transposed ? halfSize.yx : halfSize);
    bool drawn = intensity > 0.0 && !isinf(intensity);
    gl_Position = drawn ? vec4(p / frameSize * 2.0 - 1.0, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
