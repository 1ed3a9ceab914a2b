#version 450 core
// tonemapAcesFitted (src/core/Tonemap.cpp) on the GPU: Narkowicz's ACES fit per channel of
// exposure x colour, alpha untouched. The exposure comes from a 1x1 texture (the temporal
// filter's adapted exposure) so the CPU never reads it.
layout(binding = 0) uniform sampler2D hdrColor;
layout(binding = 1) uniform sampler2D exposureTexture;
uniform int exposureChannel;  // -1: exposure 1
out vec4 display;
void main() {
    vec4 c = texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0);
    float exposure = exposureChannel < 0 ? 1.0 : texelFetch(exposureTexture, ivec2(0), 0)[exposureChannel];
    vec3 x = max(vec3(0.0), c.rgb * exposure);
    display = vec4(clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0), c.a);
}
