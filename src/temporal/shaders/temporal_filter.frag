#version 450 core
// SPDX-License-Identifier: Apache-2.0
// TemporalFilter::update (src/temporal/TemporalFilter.cpp) on the GPU, line for line: one
// 1x1 fragment reads the previous state and the method's raw coverage and writes the new
// state (coverage, edge fade, exposure, flare weight). Edge fade comes from the CPU: it needs
// only where the sun projects, which the CPU knows from the camera.
layout(binding = 0) uniform sampler2D previousState;
layout(binding = 1) uniform sampler2D rawCoverage;
uniform int rawChannel;  // the channel of rawCoverage holding the value
uniform bool started;         // false on the first frame: start from this frame's values
uniform float dtSeconds;
uniform float attackSeconds, releaseSeconds;
uniform float adaptStrength, adaptDarkenSeconds, adaptBrightenSeconds;
uniform float edgeFadeNow;    // edgeFade(sunPixel, ...), 0 when the sun is behind the camera
uniform vec2 sunPixel;        // top-left origin, as on the CPU
uniform vec2 frameSize;
layout(location = 0) out vec4 state;
layout(location = 1) out float consumed;  // the raw coverage this frame used, for reports

float smoothingStep(float dt, float tau) {
    if (tau <= 0.0) return 1.0;
    return 1.0 - exp(-max(0.0, dt) / tau);
}

float smoothstep01(float x) {
    x = clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

void main() {
    float raw = texelFetch(rawCoverage, ivec2(0), 0)[rawChannel];
    float target = (isnan(raw) || isinf(raw)) ? 0.0 : clamp(raw, 0.0, 1.0);
    vec4 s = texelFetch(previousState, ivec2(0), 0);  // coverage, edge fade, exposure, weight
    float coverage = s.r, exposure = s.b;
    if (!started) {
        coverage = target;
    } else {
        float tau = target > coverage ? attackSeconds : releaseSeconds;
        coverage += smoothingStep(dtSeconds, tau) * (target - coverage);
    }
    float flareWeight = coverage * edgeFadeNow;
    vec2 d = sunPixel - 0.5 * frameSize;
    float offCentre = length(d) / (0.5 * length(frameSize));
    float staring = flareWeight * (1.0 - 0.5 * smoothstep01(offCentre));
    float targetExposure = 1.0 / (1.0 + adaptStrength * staring);
    if (!started) {
        exposure = targetExposure;
    } else {
        float tau = targetExposure < exposure ? adaptDarkenSeconds : adaptBrightenSeconds;
        exposure = exp(log(exposure) + smoothingStep(dtSeconds, tau) * (log(targetExposure) - log(exposure)));
    }
    state = vec4(coverage, edgeFadeNow, exposure, flareWeight);
    consumed = target;
}
