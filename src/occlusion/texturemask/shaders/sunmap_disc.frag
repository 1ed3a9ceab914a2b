#version 450 core
// Sun map, step 1 (GPG2 step 3): the sun drawn white through the sun camera, whose viewport
// the disc fills. G marks the texels of the disc for the normalisation and stays when the
// occluders (drawn next, red channel only) blacken R.
out vec4 fragColor;
void main() {
    fragColor = inSunDisc(rayThrough(gl_FragCoord.xy)) ? vec4(1.0) : vec4(0.0);
}
