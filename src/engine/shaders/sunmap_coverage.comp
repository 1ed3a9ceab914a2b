#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Texture masking (GPG2, "Texture Masking for Faster Lens Flare", Maughan 2001) for many
// lights: the application has drawn its occluders black (or grey, for what lets some light
// through) into each light's tile of the white sun-map atlas, from a camera at the eye looking
// along the light with the light's cone as its field of view (the tile's inscribed circle).
// One work group per light sums the tile's texels inside that circle, each weighted by the
// solid angle it spans (cos^3 of its angle to the axis), so the share is uniform over the cone
// like the ray caster's; off-screen lights keep their coverage. The in-frame share comes from
// 16 x 16 directions of the cone against the frame's projection.
layout(local_size_x = 256) in;
layout(BINDING(15, 9)) uniform sampler2D sunMaps;
UNIFORMS_BEGIN(SunMapParams, 11)
UNIFORM int tileSize;  // texels a side
UNIFORM int tilesPerRow;
UNIFORMS_END
shared vec3 sums[256];    // weighted white, weight, directions in frame

void main() {
    uint light = gl_WorkGroupID.x;
    uint index = gl_LocalInvocationIndex;
    int tile = tiles[stateBase + int(light)];
    if (tile < 0) return;  // measured on the frame's depth (light_coverage.comp)
    LightView v = lightView(lights[light]);
    ivec2 origin = ivec2(tile % tilesPerRow, tile / tilesPerRow) * tileSize;
    float tanHalf = tan(min(v.halfAngle, 1.4));  // kMaxSunMapHalfAngle of Engine.cpp
    vec3 s = vec3(0.0);
    for (int k = int(index); k < tileSize * tileSize; k += 256) {
        ivec2 texel = ivec2(k % tileSize, k / tileSize);
        vec2 r = (vec2(texel) + 0.5) / float(tileSize) * 2.0 - 1.0;  // [-1, 1] across the tile
        if (dot(r, r) > 1.0) continue;
        float tan2 = dot(r, r) * tanHalf * tanHalf;
        float weight = pow(inversesqrt(1.0 + tan2), 3.0);  // cos^3 of the texel's angle
        s.xy += vec2(weight * texelFetch(sunMaps, origin + texel, 0).r, weight);
    }
    vec3 helper = abs(v.axis.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 t1 = normalize(cross(v.axis, helper));
    vec3 t2 = cross(v.axis, t1);
    vec2 pixel;
    float lightDepth;
    bool inView;
    ivec2 cell = ivec2(int(index) % 16, int(index) / 16);
    landsAt(v, coneDirection(v, t1, t2, (vec2(cell) + 0.5) / 8.0 - 1.0), pixel, lightDepth, inView);
    s.z = inView ? 1.0 : 0.0;
    sums[index] = s;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1) {
        if (index < stride) sums[index] += sums[index + stride];
        barrier();
    }
    if (index != 0u) return;
    float raw = v.inside ? 1.0 : (sums[0].y > 0.0 ? clamp(sums[0].x / sums[0].y, 0.0, 1.0) : 0.0);
    storeCoverage(light, raw, v.inside ? 1.0 : sums[0].z / 256.0);
}
