// SPDX-License-Identifier: Apache-2.0
#include "occlusion/SunDisc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gl/GlObjects.h"
#include "occlusion/SunCone.h"
#include "scene/CameraMath.h"

namespace flarekit::occlusion {

namespace {
constexpr double kPi = std::numbers::pi;
//! Rim directions projected to find the box: 64 keep the polygon within r (1 - cos(pi / 64)) =
//! 0.0012 r of the ellipse, under the box's one-pixel margin for discs up to 800 px across.
constexpr int kRimSamples = 64;
}  // namespace

SunDiscView sunDiscView(const SceneCamera& camera, int width, int height, const SceneSun& sun) {
    SunDiscView v;
    const CameraBasis b = cameraBasis(camera);
    v.right = b.right, v.up = b.up, v.forward = b.forward;
    v.tanHalfY = std::tan(camera.fovYDeg * kPi / 360.0);
    v.tanHalfX = v.tanHalfY * double(width) / double(height);
    v.width = width, v.height = height;
    const SunCone cone(sun);
    v.sun = cone.axis;
    v.chord2 = 2.0 * cone.oneMinusCos;
    if (sun.distance > 0) {
        // gluPerspective depth of the near side's view-space depth D (0.1% nearer: a surface
        // at the light itself does not hide it), (f + n)/(f - n) - 2 f n / ((f - n) D) mapped
        // to [0, 1].
        const double n = camera.nearPlane, f = camera.farPlane;
        const double depth = std::max(1e-9, 0.999 * sun.distance * dot(cone.axis, v.forward));
        const double ndc = (f + n) / (f - n) - 2 * f * n / ((f - n) * depth);
        v.lightDepth = std::clamp(0.5 * ndc + 0.5, 0.0, 1.0);
    }
    double lox = 1e300, loy = 1e300, hix = -1e300, hiy = -1e300;
    bool behind = false;
    for (int i = 0; i < kRimSamples; ++i) {
        const double phi = 2 * kPi * i / kRimSamples;
        const Vec3 d = cone.rim(phi);
        const double z = dot(d, v.forward);
        if (z <= 1e-9) {
            behind = true;
            continue;
        }
        const double px = (dot(d, v.right) / z / v.tanHalfX + 1) * 0.5 * width;
        const double py = (dot(d, v.up) / z / v.tanHalfY + 1) * 0.5 * height;
        lox = std::min(lox, px), hix = std::max(hix, px), loy = std::min(loy, py),
        hiy = std::max(hiy, py);
    }
    v.bounded = !behind;
    v.rimX0 = lox, v.rimX1 = hix, v.rimY0 = loy, v.rimY1 = hiy;
    if (behind) {
        // Part of the rim is behind the camera plane: the projection is unbounded; look at the
        // whole frame (the weights decide what is in the disc), unless the centre is behind too.
        if (dot(v.sun, v.forward) <= 0) return v;
        lox = loy = -1e300, hix = hiy = 1e300;
    }
    auto clampTo = [](double value, int hi) { return int(std::clamp(value, 0.0, double(hi))); };
    v.x0 = clampTo(std::floor(lox) - 1, width), v.x1 = clampTo(std::ceil(hix) + 1, width);
    v.y0 = clampTo(std::floor(loy) - 1, height), v.y1 = clampTo(std::ceil(hiy) + 1, height);
    return v;
}

// ---- Same as sun_disc.glsl ----

Vec3 rayThrough(const SunDiscView& v, double px, double py) {
    const double ndcX = px / v.width * 2.0 - 1.0, ndcY = py / v.height * 2.0 - 1.0;
    return normalize(v.forward + v.right * (ndcX * v.tanHalfX) + v.up * (ndcY * v.tanHalfY));
}

bool inSunDisc(const SunDiscView& v, Vec3 d) {
    const Vec3 e = d - v.sun;
    return dot(e, e) <= v.chord2;
}

double discWeight(const SunDiscView& v, int x, int y) {
    int inside = 0;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            if (inSunDisc(v, rayThrough(v, x + (i + 0.5) / 4.0, y + (j + 0.5) / 4.0))) ++inside;
    const double cosTheta = dot(rayThrough(v, x + 0.5, y + 0.5), v.forward);
    return double(inside) / 16.0 * cosTheta * cosTheta * cosTheta;
}

// ----

void setSunDiscUniforms(GLuint p, const SunDiscView& v) {
    gl::setUniform(p, "camRight", v.right);
    gl::setUniform(p, "camUp", v.up);
    gl::setUniform(p, "camForward", v.forward);
    gl::setUniform(p, "sunDir", v.sun);
    glProgramUniform2f(p, gl::uniformLocation(p, "tanHalfFov"), float(v.tanHalfX),
                       float(v.tanHalfY));
    glProgramUniform2f(p, gl::uniformLocation(p, "frameSize"), float(v.width), float(v.height));
    glProgramUniform1f(p, gl::uniformLocation(p, "sunChord2"), float(v.chord2));
    glProgramUniform1f(p, gl::uniformLocation(p, "lightDepth"), float(v.lightDepth));
}

}  // namespace flarekit::occlusion
