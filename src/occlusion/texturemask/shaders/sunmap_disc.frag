#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Sun map, step 1 (GPG2 step 3): the sun drawn white through the sun camera, whose viewport
// the disc fills. G marks the texels of the disc for the normalisation and stays when the
// occluders (drawn next, red channel only) blacken R. A multisampled map is shaded per sample
// (reading gl_SamplePosition asks for that), so the disc's rim is resolved to the samples too.
out vec4 fragColor;
void main() {
#ifdef PER_SAMPLE
    vec2 p = floor(gl_FragCoord.xy) + gl_SamplePosition;
#else
    vec2 p = gl_FragCoord.xy;
#endif
    fragColor = inSunDisc(rayThrough(p)) ? vec4(1.0) : vec4(0.0);
}
