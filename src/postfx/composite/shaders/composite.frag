// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/composite/Composite.h: input + upsampled lens, then the display curve.
layout(binding = 0) uniform sampler2D inputImage;
layout(binding = 1) uniform sampler2D lens;
uniform vec2 invOutSize;
uniform int toneOperator;
uniform float exposure;
out vec4 result;

void main() {
    precise vec4 color = texelFetch(inputImage, ivec2(gl_FragCoord.xy), 0) + rgbOnly(bilinear(lens, pixelUv(invOutSize)));
    result = toneMap(color, toneOperator, exposure);
}
