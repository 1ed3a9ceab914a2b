// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/downsample/Downsample.h: Jimenez's 13-tap downsample.
layout(binding = 0) uniform sampler2D source;
uniform vec2 invOutSize, srcTexel;
out vec4 result;

vec4 at(vec2 uv, float dx, float dy) {
    precise vec2 p = vec2(uv.x + dx * srcTexel.x, uv.y + dy * srcTexel.y);
    return bilinear(source, p);
}

void main() {
    vec2 uv = pixelUv(invOutSize);
    vec4 a = at(uv, -2, -2), b = at(uv, 0, -2), c = at(uv, 2, -2);
    vec4 d = at(uv, -2, 0), e = at(uv, 0, 0), f = at(uv, 2, 0);
    vec4 g = at(uv, -2, 2), h = at(uv, 0, 2), i = at(uv, 2, 2);
    vec4 j = at(uv, -1, -1), k = at(uv, 1, -1), l = at(uv, -1, 1), m = at(uv, 1, 1);
    precise vec4 sum = e * 0.125 + (a + c + g + i) * 0.03125 + (b + d + f + h) * 0.0625 + (j + k + l + m) * 0.125;
    result = sum;
}
