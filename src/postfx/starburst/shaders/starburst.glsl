// SPDX-License-Identifier: Apache-2.0
// Twin of src/postfx/starburst/Starburst.h: modulation by angle about each bright source.
uniform float starIntensity, starWidth;
uniform int starSpokes;
uniform float starRays[FK_MAX_SPOKES];
uniform int starCentreCount;
uniform vec2 starCentres[FK_MAX_STAR_CENTRES];

float rayProfile(float d, float width) {
    precise float t = max(0.0, 1.0 - (d / width) * (d / width));
    return t * t;
}

float starAbout(vec2 uv, vec2 c, float aspect) {
    precise vec2 q = vec2((uv.x - c.x) * 2.0 * aspect, (uv.y - c.y) * 2.0);
    float angle = (q.x == 0.0 && q.y == 0.0) ? 0.0 : atan(q.y, q.x);
    precise float t = (angle * (0.5 / 3.14159265358979) + 0.5) * float(starSpokes);
    float k = floor(t);
    precise float f = t - k;
    int ray = int(k) % starSpokes, next = (int(k) + 1) % starSpokes;
    return starRays[ray] * rayProfile(f, starWidth) + starRays[next] * rayProfile(1.0 - f, starWidth);
}

float starburstModulation(vec2 uv, float aspect) {
    if (starIntensity == 0.0) return 1.0;
    float star = 0.0;
    for (int i = 0; i < starCentreCount; ++i) star = max(star, starAbout(uv, starCentres[i], aspect));
    return max(0.0, 1.0 - starIntensity + 2.0 * starIntensity * star);
}
