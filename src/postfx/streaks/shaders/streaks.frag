// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/streaks/Streaks.h: one 4-tap pass of a one-sided streak chain.
layout(binding = 0) uniform sampler2D source;
layout(binding = 1) uniform sampler2D other;
uniform int step, addOther;
uniform float weights[FK_STREAK_TAPS];
uniform float threshold;
uniform vec4 outScale;
out vec4 result;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int width = textureSize(source, 0).x;
    precise vec4 sum = vec4(0.0);
    for (int k = 0; k < FK_STREAK_TAPS; ++k) {
        int sx = p.x + k * step;
        if (sx >= 0 && sx < width) sum += max(texelFetch(source, ivec2(sx, p.y), 0) - threshold, vec4(0.0)) * weights[k];
    }
    if (addOther != 0) sum += texelFetch(other, p, 0);
    result = rgbOnly(sum * outScale);
}
