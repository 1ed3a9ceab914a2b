// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/brightpass/BrightPass.h (read that for the why).
layout(binding = 0) uniform sampler2D inputImage;
uniform float threshold, knee, ceiling;
uniform vec2 invOutSize;
out vec4 result;

const float kBrightEpsilon = 1e-5;

vec4 softThreshold(vec4 color, float threshold, float knee) {
    float brightness = max(color.r, max(color.g, color.b));
    precise float soft = clamp(brightness - threshold + knee, 0.0, 2.0 * knee);
    soft = soft * soft / (4.0 * knee + kBrightEpsilon);
    precise float weight = max(soft, brightness - threshold) / max(brightness, kBrightEpsilon);
    return rgbOnly(color * weight);
}

vec4 compressHighlights(vec4 color, float ceiling) {
    if (ceiling <= 0.0) return color;
    float brightness = max(color.r, max(color.g, color.b));
    precise float e = exp(-2.0 * brightness / ceiling);
    precise float compressed = ceiling * (1.0 - e) / (1.0 + e);
    return color * (compressed / max(brightness, kBrightEpsilon));
}

void main() {
    vec4 color = compressHighlights(bilinearLight(inputImage, pixelUv(invOutSize)), ceiling);
    result = softThreshold(color, threshold, knee);
}
