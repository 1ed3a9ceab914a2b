#version 450 core
// SPDX-License-Identifier: Apache-2.0
// A translucent object's share of light let through, multiplied into the transmittance target
// (blend: destination x source), so each pixel ends as the product over the translucent
// surfaces in front of the opaque depth, once per object (closed objects draw front faces).
uniform float opacity;
out vec4 fragColor;
void main() { fragColor = vec4(1.0 - opacity); }
