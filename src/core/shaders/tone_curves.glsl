// SPDX-License-Identifier: Apache-2.0
// Twin of src/core/ToneCurves.h: Narkowicz's ACES fit and Hable's filmic curve.
float acesFitted(float x) {
    precise float y = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    return clamp(y, 0.0, 1.0);
}

float hablePartial(float x) {
    const float a = 0.15, b = 0.50, c = 0.10, d = 0.20, e = 0.02, f = 0.30;
    precise float y = (x * (a * x + c * b) + d * e) / (x * (a * x + b) + d * f) - e / f;
    return y;
}

float hableFilmic(float x) {
    const float kWhite = 11.2, kExposureBias = 2.0;
    return clamp(hablePartial(x * kExposureBias) / hablePartial(kWhite), 0.0, 1.0);
}
