#version 450 core
// SPDX-License-Identifier: Apache-2.0
// A ghost mesh's vertex in image pixels (x right, y down) with what the fragment stage weighs;
// the geometry stage hands all three of a triangle's vertices to every fragment, which then
// interpolates exactly as the CPU rasteriser does (src/lens/LensRender.cpp).
layout(location = 0) in vec2 a_pixel;
layout(location = 1) in vec4 a_attributesA;  // throughput, largest r / semi-aperture, stop 0
layout(location = 2) in vec4 a_attributesB;  // stops 1 and 2 (normalised stop coordinates)
layout(location = 3) in float a_density;     // irradiance factor (the same on all three)

uniform float u_side;    // the viewport's side: a power of two, so these maps are exact
uniform float u_height;  // the image's height in pixels

out vec2 v_pixel;
out vec4 v_attributesA;
out vec4 v_attributesB;
out float v_density;

void main() {
    v_pixel = a_pixel;
    v_attributesA = a_attributesA;
    v_attributesB = a_attributesB;
    v_density = a_density;
    // Window x = pixel x and window y = height - pixel y (GL counts rows from the bottom), with
    // no rounding: the vertices' 1/256 steps reach the rasteriser as they are.
    gl_Position = vec4(2.0 * a_pixel.x / u_side - 1.0, 2.0 * (u_height - a_pixel.y) / u_side - 1.0,
                       0.0, 1.0);
}
