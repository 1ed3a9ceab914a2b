#version 450 core
// texture-mask-screen: the sun map built from the main frame's depth instead of a re-render.
// Each texel's ray (through the sun camera, below) is projected into the main frame; it is
// sun (R = 1) when the main frame shows sky there. G marks texels that are in the disc and
// on screen, so off-screen parts drop out of the normalisation.
uniform vec3 mapRight, mapUp, mapForward;  // the sun camera
uniform float mapTanHalf;
uniform float mapSize;
layout(binding = 0) uniform sampler2D sceneDepth;
out vec4 fragColor;
void main() {
    vec2 ndc = gl_FragCoord.xy / mapSize * 2.0 - 1.0;
    vec3 d = normalize(mapForward + (mapRight * ndc.x + mapUp * ndc.y) * mapTanHalf);
    fragColor = vec4(0.0);
    if (!inSunDisc(d)) return;
    float z = dot(d, camForward);
    if (z <= 0.0) return;
    vec2 pixel = (vec2(dot(d, camRight), dot(d, camUp)) / z / tanHalfFov * 0.5 + 0.5) * frameSize;
    if (any(lessThan(pixel, vec2(0.0))) || any(greaterThanEqual(pixel, frameSize))) return;
    float depth = texelFetch(sceneDepth, ivec2(pixel), 0).r;
    fragColor = vec4(depth >= 1.0 ? 1.0 : 0.0, 1.0, 0.0, 1.0);
}
