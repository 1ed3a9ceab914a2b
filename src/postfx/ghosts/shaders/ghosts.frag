// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/ghosts/Ghosts.h: the seed's LensFlarePS, one iteration per ghost.
layout(binding = 0) uniform sampler2D bloom;
uniform vec2 invOutSize, sourceTexel;
uniform int ghostCount;
uniform float intensity;
uniform vec3 tints[FK_MAX_GHOSTS];
uniform float scales[FK_MAX_GHOSTS], blurs[FK_MAX_GHOSTS], thresholds[FK_MAX_GHOSTS], falloffs[FK_MAX_GHOSTS];
uniform float borderFades[FK_MAX_GHOSTS];
uniform int sampleCounts[FK_MAX_GHOSTS], centered[FK_MAX_GHOSTS], useBilinear[FK_MAX_GHOSTS];
out vec4 result;

vec4 ghostPixel(int g, vec2 uv) {
    precise vec2 n = vec2(((1.0 - uv.x) * 2.0 - 1.0) * scales[g], ((1.0 - uv.y) * 2.0 - 1.0) * scales[g]);
    precise float len = sqrt(n.x * n.x + n.y * n.y);
    precise vec2 toward = len > 0.0 ? vec2(-n.x / len, -n.y / len) : vec2(0.0);
    precise float dist = blurs[g] * float(sampleCounts[g]);
    precise vec2 unit = vec2(toward.x * sourceTexel.x * dist, toward.y * sourceTexel.y * dist);
    float first = centered[g] != 0 ? float(sampleCounts[g] - 1) : 1.0;
    float weight = centreFalloff(n, falloffs[g]);
    vec3 base = tints[g];  // ghostTint, applied on the CPU side
    vec4 tint = vec4(base * weight, 0.0);
    precise vec4 sum = vec4(0.0);
    for (int i = 0; i < sampleCounts[g]; ++i) {
        precise float offset = first - 2.0 * float(i);
        precise vec2 p = vec2(n.x + unit.x * offset, n.y + unit.y * offset);
        precise vec2 s = vec2(p.x * 0.5 + 0.5, p.y * 0.5 + 0.5);
        if (s.x >= 0.0 && s.x <= 1.0 && s.y >= 0.0 && s.y <= 1.0) {
            vec4 texel = useBilinear[g] != 0 ? bilinear(bloom, s) : pointSample(bloom, s);
            sum += max(texel - thresholds[g], vec4(0.0)) * tint * borderWindow(s, borderFades[g]);
        }
    }
    return sum / float(sampleCounts[g]);
}

void main() {
    vec2 uv = pixelUv(invOutSize);
    precise vec4 total = vec4(0.0);
    for (int g = 0; g < ghostCount; ++g) total += ghostPixel(g, uv);
    result = rgbOnly(total * intensity);
}
