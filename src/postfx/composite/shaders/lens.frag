// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/composite/Lens.h: bloom + flare, times dirt.
layout(binding = 0) uniform sampler2D bloom;
layout(binding = 1) uniform sampler2D ghosts;
layout(binding = 2) uniform sampler2D halo;
layout(binding = 3) uniform sampler2D streaks;
layout(binding = 4) uniform sampler2D dirt;
uniform vec2 invOutSize;
uniform float aspect, bloomIntensity, chromatic, dirtIntensity;
out vec4 result;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 uv = pixelUv(invOutSize);
    precise vec4 flare = chromaticFlare(ghosts, halo, uv, chromatic) * starburstModulation(uv, aspect) +
                         texelFetch(streaks, p, 0);
    precise vec4 lens = texelFetch(bloom, p, 0) * bloomIntensity + flare;
    if (dirtIntensity > 0.0) lens = lens * (1.0 + dirtIntensity * texelFetch(dirt, p, 0).r);
    result = rgbOnly(lens);
}
