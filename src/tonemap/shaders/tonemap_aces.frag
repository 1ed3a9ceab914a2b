// SPDX-License-Identifier: Apache-2.0
// tonemapAcesFitted (src/core/Tonemap.cpp) on the GPU: acesFitted (tone_curves.glsl, linked
// in front of this) per channel of exposure x colour, alpha untouched. The exposure comes from
// a 1x1 texture (the temporal filter's adapted exposure) so the CPU never reads it.
layout(binding = 0) uniform sampler2D hdrColor;
layout(binding = 1) uniform sampler2D exposureTexture;
uniform int exposureChannel;  // -1: exposure 1
out vec4 display;
void main() {
    vec4 c = texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0);
    float exposure = exposureChannel < 0 ? 1.0 : texelFetch(exposureTexture, ivec2(0), 0)[exposureChannel];
    vec3 x = max(vec3(0.0), c.rgb * exposure);
    display = vec4(acesFitted(x.r), acesFitted(x.g), acesFitted(x.b), c.a);
}
