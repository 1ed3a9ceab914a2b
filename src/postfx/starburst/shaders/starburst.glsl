// Twin of src/postfx/starburst/Starburst.h: modulation by angle about the centre.
uniform float starIntensity, starWidth;
uniform int starSpokes;
uniform float starRays[FK_MAX_SPOKES];

float rayProfile(float d, float width) {
    precise float t = max(0.0, 1.0 - (d / width) * (d / width));
    return t * t;
}

float starburstModulation(vec2 uv, float aspect) {
    if (starIntensity == 0.0) return 1.0;
    precise vec2 q = vec2((uv.x * 2.0 - 1.0) * aspect, uv.y * 2.0 - 1.0);
    float angle = (q.x == 0.0 && q.y == 0.0) ? 0.0 : atan(q.y, q.x);
    precise float t = (angle * (0.5 / 3.14159265358979) + 0.5) * float(starSpokes);
    float k = floor(t);
    precise float f = t - k;
    int ray = int(k) % starSpokes, next = (int(k) + 1) % starSpokes;
    precise float star = starRays[ray] * rayProfile(f, starWidth) + starRays[next] * rayProfile(1.0 - f, starWidth);
    return max(0.0, 1.0 - starIntensity + 2.0 * starIntensity * star);
}
