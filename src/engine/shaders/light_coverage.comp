#version 450 core
// SPDX-License-Identifier: Apache-2.0
// The engine's batched occlusion: one work group per light, 256 threads casting up to
// perSide^2 stratified, jittered directions (the ray caster's sampling) into the frame's
// depth. A direction counts as seen where the stored depth is at or beyond the light's own
// depth there (times the transmittance texture, if any); directions outside the view count
// as unseen (a screen method reports what is in frame), unless the application rendered a
// guard band around the view, which is then read too. Thread 0 writes the light's raw
// coverage and in-frame share, steps its temporal filter (attack / release, as
// TemporalFilter) and stores the filtered value in the coverage texture. Built twice: with
// MULTISAMPLE defined a direction reads the depth sample of its pixel nearest to it.
layout(local_size_x = 256) in;
UNIFORMS_BEGIN(CoverageParams, 11)
UNIFORM int perSide;          // directions per side for a light large on screen
UNIFORM int samplesPerPixel;  // depth samples per pixel (1, or the MSAA count)
UNIFORM bool hasTransmittance;
UNIFORM int sampleCount;
UNIFORM vec2 samplePositions[16];  // within the pixel, [0, 1)^2 (glGetMultisamplefv)
UNIFORMS_END
#ifdef MULTISAMPLE
layout(BINDING(15, 5)) uniform sampler2DMS depthSamples;
float depthAt(vec2 p) {
    vec2 inPixel = fract(p);
    int nearest = 0;
    float best = 4.0;
    for (int i = 0; i < sampleCount; ++i) {
        vec2 d = samplePositions[i] - inPixel;
        if (dot(d, d) < best) best = dot(d, d), nearest = i;
    }
    return texelFetch(depthSamples, ivec2(p), nearest).r;
}
#else
layout(BINDING(15, 5)) uniform sampler2D depthTexture;
float depthAt(vec2 p) { return texelFetch(depthTexture, ivec2(p), 0).r; }
#endif
layout(BINDING(14, 6)) uniform sampler2D transmittance;

shared vec2 sums[256];

void main() {
    uint light = gl_WorkGroupID.x;
    uint index = gl_LocalInvocationIndex;
    if (tiles[stateBase + int(light)] >= 0) return;  // too small for the depth: its sun map
    LightView v = lightView(lights[light]);
    vec3 helper = abs(v.axis.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 t1 = normalize(cross(v.axis, helper));
    vec3 t2 = cross(v.axis, t1);
    // Directions per side: about 16 per depth sample the light covers, up to perSide. A
    // light a few pixels wide is resolved by its few samples, not by more directions (its
    // error is the depth's quantization); this keeps a street of distant lamps cheap.
    float radiusPx = tan(min(v.halfAngle, 1.4)) * abs(projectionMatrix[1][1]) * 0.5 * float(viewport.w);
    float covered = 3.14159265 * radiusPx * radiusPx * float(samplesPerPixel);
    int side = clamp(int(ceil(sqrt(16.0 * covered))), min(8, perSide), perSide);
    int total = side * side;
    vec2 s = vec2(0.0);  // seen (weighted by transmittance), in frame
    for (int k = int(index); k < total && !v.inside; k += 256) {
        uint h = pcgHash(uint(k) ^ pcgHash(light));
        vec2 jitter = vec2(h & 0xffffu, h >> 16) / 65536.0;
        vec2 ab = 2.0 * (vec2(k % side, k / side) + jitter) / float(side) - 1.0;
        vec2 pixel;
        float lightDepth;
        bool inView;
        bool readable = landsAt(v, coneDirection(v, t1, t2, ab), pixel, lightDepth, inView);
        if (!readable) {
            s.y += inView ? 1.0 : 0.0;
            continue;
        }
        float stored = depthAt(pixel);
        bool seen = depthConvention == 2 ? stored <= lightDepth : stored >= lightDepth;
        float kept = hasTransmittance ? texture(transmittance, pixel / depthTextureSize).r : 1.0;
        s += vec2(seen ? clamp(kept, 0.0, 1.0) : 0.0, inView ? 1.0 : 0.0);
    }
    sums[index] = s;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1) {
        if (index < stride) sums[index] += sums[index + stride];
        barrier();
    }
    if (index != 0u) return;
    vec2 share = v.inside ? vec2(1.0) : sums[0] / float(total);
    storeCoverage(light, share.x, share.y);
}
