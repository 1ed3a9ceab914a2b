// SPDX-License-Identifier: Apache-2.0
#include "scene/CameraMath.h"

#include <cmath>
#include <numbers>

namespace flarekit {

CameraBasis cameraBasis(const SceneCamera& c) {
    const Vec3 f = normalize(c.lookAt - c.position);
    const Vec3 s = normalize(cross(f, c.up));
    return {s, cross(s, f), f};
}

Mat4 lookAtMatrix(const SceneCamera& c) {
    const CameraBasis b = cameraBasis(c);
    const Vec3 s = b.right, u = b.up, f = b.forward;
    const Vec3 p = c.position;
    // A column a line.
    // clang-format off
    return {s.x,        u.x,        -f.x,      0,
            s.y,        u.y,        -f.y,      0,
            s.z,        u.z,        -f.z,      0,
            -dot(s, p), -dot(u, p), dot(f, p), 1};
    // clang-format on
}

Mat4 perspectiveMatrix(const SceneCamera& c, double aspect) {
    const double f = 1.0 / std::tan(c.fovYDeg * std::numbers::pi / 360.0);
    const double n = c.nearPlane, fa = c.farPlane;
    // A column a line.
    // clang-format off
    return {f / aspect, 0, 0,                     0,
            0,          f, 0,                     0,
            0,          0, (fa + n) / (n - fa),   -1,
            0,          0, 2 * fa * n / (n - fa), 0};
    // clang-format on
}

Mat4 orthographicMatrix(double halfWidth, double halfHeight, double nearPlane, double farPlane) {
    Mat4 m{};
    m[0] = 1 / halfWidth;
    m[5] = 1 / halfHeight;
    m[10] = -2 / (farPlane - nearPlane);
    m[14] = -(farPlane + nearPlane) / (farPlane - nearPlane);
    m[15] = 1;
    return m;
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 r{};
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            double sum = 0;
            for (int k = 0; k < 4; ++k)
                sum += a[std::size_t(k * 4 + row)] * b[std::size_t(col * 4 + k)];
            r[std::size_t(col * 4 + row)] = sum;
        }
    }
    return r;
}

Mat4 inverse(const Mat4& m) {
    // Cofactor expansion (as in the MESA GLU implementation's algorithm, written out here).
    Mat4 inv{};
    inv[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] +
             m[9] * m[7] * m[14] + m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
    inv[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] -
             m[8] * m[7] * m[14] - m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
    inv[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] +
             m[8] * m[7] * m[13] + m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
    inv[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] -
              m[8] * m[6] * m[13] - m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
    inv[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] -
             m[9] * m[3] * m[14] - m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
    inv[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] +
             m[8] * m[3] * m[14] + m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
    inv[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] -
             m[8] * m[3] * m[13] - m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
    inv[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] +
              m[8] * m[2] * m[13] + m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
    inv[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] + m[5] * m[3] * m[14] +
             m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
    inv[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] -
             m[4] * m[3] * m[14] - m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
    inv[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] +
              m[4] * m[3] * m[13] + m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
    inv[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] -
              m[4] * m[2] * m[13] - m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
    inv[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] -
             m[5] * m[3] * m[10] - m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
    inv[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] + m[4] * m[3] * m[10] +
             m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
    inv[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] - m[4] * m[3] * m[9] -
              m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
    inv[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] + m[4] * m[2] * m[9] +
              m[8] * m[1] * m[6] - m[8] * m[2] * m[5];
    const double det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
    for (double& v : inv) v /= det;
    return inv;
}

std::array<float, 16> toFloat(const Mat4& m) {
    std::array<float, 16> f{};
    for (std::size_t i = 0; i < 16; ++i) f[i] = float(m[i]);
    return f;
}

namespace {
bool projectHomogeneous(const Scene& scene, double x, double y, double z, double w, Point& pixel) {
    const Mat4 vp = multiply(perspectiveMatrix(scene.camera, double(scene.width) / scene.height),
                             lookAtMatrix(scene.camera));
    const double cx = vp[0] * x + vp[4] * y + vp[8] * z + vp[12] * w;
    const double cy = vp[1] * x + vp[5] * y + vp[9] * z + vp[13] * w;
    const double cw = vp[3] * x + vp[7] * y + vp[11] * z + vp[15] * w;
    if (cw <= 0) return false;
    pixel = {float((cx / cw + 1) * 0.5 * scene.width), float((1 - cy / cw) * 0.5 * scene.height)};
    return true;
}
}  // namespace

bool projectDirection(const Scene& scene, Vec3 d, Point& pixel) {
    return projectHomogeneous(scene, d.x, d.y, d.z, 0, pixel);
}
bool projectPoint(const Scene& scene, Vec3 p, Point& pixel) {
    return projectHomogeneous(scene, p.x, p.y, p.z, 1, pixel);
}

}  // namespace flarekit
