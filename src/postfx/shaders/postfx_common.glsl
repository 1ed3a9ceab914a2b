// SPDX-License-Identifier: Apache-2.0
// The twin of src/postfx/Kernel.h: clamped fetches, the seed's point sampler and bilinear
// filtering written out by hand, so the GL chain filters exactly like the CPU chain (hardware
// filtering rounds its weights to 8 bits on most GPUs). `precise` keeps the compiler from
// fusing multiply-adds the CPU does as two roundings.
vec4 fetchClamped(sampler2D t, ivec2 p) {
    return texelFetch(t, clamp(p, ivec2(0), textureSize(t, 0) - 1), 0);
}

vec4 pointSample(sampler2D t, vec2 uv) {
    precise vec2 s = uv * vec2(textureSize(t, 0));
    return fetchClamped(t, ivec2(floor(s)));
}

vec4 fetchLight(sampler2D t, ivec2 p) {
    vec4 v = fetchClamped(t, p);
    for (int i = 0; i < 4; ++i) {
        if (isnan(v[i]) || isinf(v[i]) || v[i] < 0.0) v[i] = 0.0;
    }
    return v;
}

// The body of bilinear, fetching through FETCH (a macro: GLSL has no function parameters).
#define BILINEAR_BODY(FETCH)                                                  \
    precise vec2 s = uv * vec2(textureSize(t, 0)) - 0.5;                      \
    vec2 i = floor(s);                                                        \
    precise vec2 f = s - i;                                                   \
    ivec2 p = ivec2(i);                                                       \
    vec4 a = FETCH(t, p), b = FETCH(t, p + ivec2(1, 0));                      \
    vec4 c = FETCH(t, p + ivec2(0, 1)), d = FETCH(t, p + ivec2(1, 1));        \
    precise vec4 top = a + (b - a) * f.x;                                     \
    precise vec4 bottom = c + (d - c) * f.x;                                  \
    precise vec4 result = top + (bottom - top) * f.y;                         \
    return result;

vec4 bilinear(sampler2D t, vec2 uv) { BILINEAR_BODY(fetchClamped) }
vec4 bilinearLight(sampler2D t, vec2 uv) { BILINEAR_BODY(fetchLight) }

vec2 pixelUv(vec2 invSize) { precise vec2 uv = gl_FragCoord.xy * invSize; return uv; }
vec4 rgbOnly(vec4 v) { return vec4(v.rgb, 0.0); }

// 1 / sqrt(2): the centre-to-corner distance in [-1, 1] coordinates is sqrt(2).
const float kInvCornerDistance = 0.70710678;

float centreFalloff(vec2 p, float exponent) {
    if (exponent <= 0.0) return 1.0;
    precise float r = sqrt(p.x * p.x + p.y * p.y) * kInvCornerDistance;
    return pow(max(0.0, 1.0 - r), exponent);
}

float borderWindow(vec2 s, float fade) {
    if (fade <= 0.0) return 1.0;
    precise float tx = clamp(min(s.x, 1.0 - s.x) / fade, 0.0, 1.0);
    precise float ty = clamp(min(s.y, 1.0 - s.y) / fade, 0.0, 1.0);
    precise float w = tx * tx * (3.0 - 2.0 * tx) * (ty * ty * (3.0 - 2.0 * ty));
    return w;
}
