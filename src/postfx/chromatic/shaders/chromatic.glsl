// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/chromatic/Chromatic.h: red outward, blue inward.
vec4 flareAt(sampler2D ghosts, sampler2D halo, vec2 uv) {
    precise vec4 sum = bilinear(ghosts, uv) + bilinear(halo, uv);
    return sum;
}

vec4 chromaticFlare(sampler2D ghosts, sampler2D halo, vec2 uv, float amount) {
    if (amount == 0.0) return flareAt(ghosts, halo, uv);
    precise vec2 d = vec2(uv.x - 0.5, uv.y - 0.5);
    precise vec2 outward = vec2(0.5 + d.x * (1.0 + amount), 0.5 + d.y * (1.0 + amount));
    precise vec2 inward = vec2(0.5 + d.x * (1.0 - amount), 0.5 + d.y * (1.0 - amount));
    float red = flareAt(ghosts, halo, outward).r;
    float green = flareAt(ghosts, halo, uv).g;
    float blue = flareAt(ghosts, halo, inward).b;
    return vec4(red, green, blue, 0.0);
}
