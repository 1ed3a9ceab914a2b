// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/blur/Upsample.h: U(k) = (D(k) + spread * tent(U(k+1))) * scale.
layout(binding = 0) uniform sampler2D fine;
layout(binding = 1) uniform sampler2D coarse;
uniform vec2 invOutSize, coarseTexel;
uniform float spread, scale;
out vec4 result;

vec4 at(vec2 uv, float dx, float dy) {
    precise vec2 p = vec2(uv.x + dx * coarseTexel.x, uv.y + dy * coarseTexel.y);
    return bilinear(coarse, p);
}

void main() {
    vec2 uv = pixelUv(invOutSize);
    precise vec4 corners = at(uv, -1, -1) + at(uv, 1, -1) + at(uv, -1, 1) + at(uv, 1, 1);
    precise vec4 edges = at(uv, 0, -1) + at(uv, -1, 0) + at(uv, 1, 0) + at(uv, 0, 1);
    precise vec4 tent = (corners + edges * 2.0 + at(uv, 0, 0) * 4.0) * 0.0625;
    precise vec4 sum = (texelFetch(fine, ivec2(gl_FragCoord.xy), 0) + tent * spread) * scale;
    result = sum;
}
