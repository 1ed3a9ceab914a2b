// SPDX-License-Identifier: Apache-2.0
// Per light and view: the raw coverage, its temporally filtered value (attack / release, as
// TemporalFilter of flarekit/Temporal.h) and the in-frame share, in the state buffer, and the
// filtered value in the coverage texture the application and the flare draw read. Prepended
// to both occlusion passes (light_coverage.comp, sunmap_coverage.comp); each light is
// measured by exactly one of them, the one its entry of `tiles` names.
layout(std430, BINDING(7, 2)) buffer State { vec4 state[]; };  // raw, filtered, in frame, started
// Per light and view: its sun-map tile, or -1 where the frame's depth measures it
// (Engine::Impl::assignTiles: texture-mask tiles every light, compute the small ones).
layout(std430, BINDING(5, 3)) readonly buffer Tiles { int tiles[]; };
layout(r32f, BINDING(7, 4)) uniform writeonly image2D filteredCoverage;
UNIFORMS_BEGIN(StateParams, 10)
UNIFORM int viewIndex;
UNIFORM int stateBase;     // viewIndex x max lights
UNIFORM float attackStep;  // 1 - exp(-dt / tau), from the CPU
UNIFORM float releaseStep;
UNIFORMS_END

void storeCoverage(uint light, float raw, float inFrame) {
    vec4 previous = state[stateBase + int(light)];
    float filtered = raw;
    if (previous.w > 0.5) {
        float step = raw > previous.y ? attackStep : releaseStep;
        filtered = previous.y + step * (raw - previous.y);
    }
    state[stateBase + int(light)] = vec4(raw, filtered, inFrame, 1.0);
    imageStore(filteredCoverage, ivec2(int(light), viewIndex), vec4(filtered));
}

// A 32-bit integer hash (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering", pcg).
uint pcgHash(uint v) {
    uint h = v * 747796405u + 2891336453u;
    uint word = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    return (word >> 22u) ^ word;
}
