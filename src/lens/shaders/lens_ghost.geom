#version 450 core
// SPDX-License-Identifier: Apache-2.0
// Every fragment of a triangle gets its three vertices, flat: the fragment stage computes the
// barycentric weights itself, relative to the triangle (as the CPU does), rather than trusting
// the rasteriser's interpolation, whose float error the masks' steep soft edges would magnify.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec2 v_pixel[];
in vec4 v_attributesA[];
in vec4 v_attributesB[];
in float v_density[];

flat out vec2 g_pixel0, g_pixel1, g_pixel2;
flat out vec4 g_attributesA0, g_attributesA1, g_attributesA2;
flat out vec4 g_attributesB0, g_attributesB1, g_attributesB2;
flat out float g_density;

void main() {
    for (int i = 0; i < 3; ++i) {
        g_pixel0 = v_pixel[0], g_pixel1 = v_pixel[1], g_pixel2 = v_pixel[2];
        g_attributesA0 = v_attributesA[0], g_attributesA1 = v_attributesA[1];
        g_attributesA2 = v_attributesA[2];
        g_attributesB0 = v_attributesB[0], g_attributesB1 = v_attributesB[1];
        g_attributesB2 = v_attributesB[2];
        g_density = v_density[0];
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
