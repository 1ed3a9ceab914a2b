// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/halo/Halo.h: Chapman's halo, aspect-correct.
layout(binding = 0) uniform sampler2D bloom;
uniform vec2 invOutSize;
uniform float aspect, radius, thickness, threshold, falloff, intensity, borderFade;
uniform vec3 tint;
out vec4 result;

const int kHaloSamples = FK_HALO_SAMPLES;
void main() {
    vec2 uv = pixelUv(invOutSize);
    precise vec2 m = vec2((1.0 - 2.0 * uv.x) * aspect, 1.0 - 2.0 * uv.y);
    precise float len = sqrt(m.x * m.x + m.y * m.y);
    precise vec2 dir = len > 0.0 ? vec2(m.x / len, m.y / len) : vec2(0.0);
    precise vec2 mid = vec2((m.x - dir.x * radius) / aspect, m.y - dir.y * radius);
    float weight = centreFalloff(mid, falloff);
    precise vec4 sum = vec4(0.0);
    for (int i = 0; i < kHaloSamples; ++i) {
        precise float r = radius + thickness * ((float(i) + 0.5) / float(kHaloSamples) - 0.5);
        precise vec2 p = vec2((m.x - dir.x * r) / aspect, m.y - dir.y * r);
        precise vec2 s = vec2(p.x * 0.5 + 0.5, p.y * 0.5 + 0.5);
        if (s.x >= 0.0 && s.x <= 1.0 && s.y >= 0.0 && s.y <= 1.0) {
            sum += max(bilinear(bloom, s) - threshold, vec4(0.0)) * borderWindow(s, borderFade);
        }
    }
    result = rgbOnly(sum * vec4(tint * weight, 0.0) * (intensity / float(kHaloSamples)));
}
