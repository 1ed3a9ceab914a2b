#version 450 core
// Burnout chain, pass 3: (visible x weight, weight), so the averages the chain computes give
// coverage = R / G at the end.
layout(binding = 0) uniform sampler2D mask;
out vec4 fragColor;
void main() {
    vec4 m = texelFetch(mask, ivec2(gl_FragCoord.xy), 0);
    fragColor = vec4((1.0 - m.r) * m.g, m.g, 0.0, 1.0);
}
