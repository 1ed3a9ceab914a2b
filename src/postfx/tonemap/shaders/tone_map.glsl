// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/tonemap/ToneCurves.h (needs tone_curves.glsl). op: 0 none, 1 aces, 2 filmic.
vec4 toneMap(vec4 c, int op, float exposure) {
    vec4 outColor = c;
    if (op == 0) {
        for (int i = 0; i < 3; ++i) outColor[i] = c[i] * exposure;
        return outColor;
    }
    for (int i = 0; i < 3; ++i) {
        float x = max(0.0, c[i] * exposure);
        outColor[i] = op == 1 ? acesFitted(x) : hableFilmic(x);
    }
    return outColor;
}
