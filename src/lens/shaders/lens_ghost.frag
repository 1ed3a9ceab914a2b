#version 450 core
// SPDX-License-Identifier: Apache-2.0
// The CPU rasteriser's per-pixel weight (src/lens/LensRender.cpp, rasterise()) line for line:
// the pixel centre's barycentric weights from the triangle's edge functions, the clear
// apertures' and the iris's soft masks of the interpolated coordinates, times the interpolated
// throughput, the triangle's density and the mesh's colour weight; added.
flat in vec2 g_pixel0, g_pixel1, g_pixel2;
flat in vec4 g_attributesA0, g_attributesA1, g_attributesA2;
flat in vec4 g_attributesB0, g_attributesB1, g_attributesB2;
flat in float g_density;

uniform vec3 u_weight;       // energy per channel x the triangle's entrance share
uniform int u_crossings;     // stop crossings of the path (0-3)
uniform int u_blades;        // < 3: a round iris
uniform float u_cosHalf;     // cos(pi / blades)
uniform float u_roundness;
uniform vec2 u_normals[32];  // the iris edges' outward normals
uniform float u_maskEdge;    // the masks' soft edge (kMaskEdge)
uniform float u_height;      // the image's height in pixels

out vec4 o_color;

float edgeMask(float q) { return clamp((1.0 - q) / u_maskEdge + 0.5, 0.0, 1.0); }

// irisRadius of src/lens/LensTrace.cpp.
float irisRadius(vec2 p) {
    float r = length(p);
    if (u_blades < 3) return r;
    float d = 0.0;
    for (int k = 0; k < u_blades; ++k) d = max(d, dot(p, u_normals[k]));
    d /= u_cosHalf;
    if (u_roundness <= 0.0 || r == 0.0) return d;
    return r * d / (r + (d - r) * u_roundness);
}

void main() {
    // The pixel centre in image coordinates (rows from the top), exact.
    // The edge functions and area in double, as on the CPU: with vertices on the 1/256 grid
    // their products are exact there, while in float a sliver triangle's weights (small
    // differences of large products) were off by 1e-5, which a mask's soft edge turned into
    // 1e-3 of the pixel. The rest stays in float.
    dvec2 p = dvec2(gl_FragCoord.x, u_height - gl_FragCoord.y);
    dvec2 a = g_pixel0, b = g_pixel1, c = g_pixel2;
    double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    double ea = (c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x);
    double eb = (a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x);
    double ec = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    vec3 w = vec3(dvec3(ea, eb, ec) / area);
    vec4 attributesA = w.x * g_attributesA0 + w.y * g_attributesA1 + w.z * g_attributesA2;
    vec4 attributesB = w.x * g_attributesB0 + w.y * g_attributesB1 + w.z * g_attributesB2;
    float mask = edgeMask(attributesA.y);
    if (u_crossings > 0) mask *= edgeMask(irisRadius(attributesA.zw));
    if (u_crossings > 1) mask *= edgeMask(irisRadius(attributesB.xy));
    if (u_crossings > 2) mask *= edgeMask(irisRadius(attributesB.zw));
    float v = mask * g_density * attributesA.x;
    o_color = vec4(v * u_weight, 0.0);
}
