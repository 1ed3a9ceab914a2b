// SPDX-License-Identifier: Apache-2.0
#include "engine/SunMaps.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace flarekit::engine {

namespace {

//! Sun-map tiles: 64 texels a side (about 3,200 inside the cone's circle: an edge across it is
//! placed to half a texel, under 0.01 of the disc) while the atlas stays within 4096^2; for
//! more than 4,096 lights they shrink to fit.
constexpr int kMaxTileSize = 64, kMaxAtlasSide = 4096;
//! The widest cone a tile holds: 80 degrees half-angle (tan = 5.7); a camera nearer a sphere
//! light than that is as good as inside it.
constexpr double kMaxSunMapHalfAngle = 1.4;

//! Column-major view-projection of the camera at `eye` looking along unit `axis` whose field of
//! view is the cone of half-angle `half`, to distance `farPlane`, in the clip space of the
//! frame's depth convention (so the application's clip control draws it unchanged).
std::array<float, 16> coneCamera(const double eye[3], const double axis[3], double half,
                                 double nearPlane, double farPlane,
                                 fk_depth_convention convention) {
    const double up[3] = {std::abs(axis[1]) < 0.99 ? 0.0 : 1.0,
                          std::abs(axis[1]) < 0.99 ? 1.0 : 0.0, 0.0};
    double side[3] = {axis[1] * up[2] - axis[2] * up[1], axis[2] * up[0] - axis[0] * up[2],
                      axis[0] * up[1] - axis[1] * up[0]};
    const double sl = std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]);
    for (double& c : side) c /= sl;
    const double u[3] = {side[1] * axis[2] - side[2] * axis[1],
                         side[2] * axis[0] - side[0] * axis[2],
                         side[0] * axis[1] - side[1] * axis[0]};
    const auto dot = [](const double* a, const double* b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const double view[16] = {
        side[0], u[0], -axis[0], 0, side[1],         u[1],         -axis[1],       0,
        side[2], u[2], -axis[2], 0, -dot(side, eye), -dot(u, eye), dot(axis, eye), 1};
    const double f = 1.0 / std::tan(std::min(half, kMaxSunMapHalfAngle));
    const double n = std::min(nearPlane, 0.5 * farPlane), far = farPlane;
    double proj[16] = {f, 0, 0, 0, 0, f, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0};
    if (convention == FK_DEPTH_MINUS_ONE_TO_ONE) {
        proj[10] = (far + n) / (n - far);
        proj[14] = 2 * far * n / (n - far);
    } else {
        proj[10] = far / (n - far);
        proj[14] = far * n / (n - far);
    }
    std::array<float, 16> vp{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += proj[k * 4 + r] * view[c * 4 + k];
            vp[std::size_t(c * 4 + r)] = float(sum);
        }
    return vp;
}

//! The frame's own near plane, read back from its projection under its convention: the sun
//! maps clip there too. (A plane much nearer than the scene's scale makes float clipping of
//! large triangles, a ground plane, scatter slivers over the tiny field of view of a sun map.)
double nearPlaneOf(const fk_frame& f) {
    const double p10 = f.projection[10], p14 = f.projection[14];
    double n = 0.1;
    if (f.depth_convention == FK_DEPTH_MINUS_ONE_TO_ONE && p10 != 1.0)
        n = p14 / (p10 - 1.0);
    else if (f.depth_convention == FK_DEPTH_ZERO_TO_ONE && p10 != 0.0)
        n = p14 / p10;
    else if (f.depth_convention == FK_DEPTH_REVERSED_Z && p10 != -1.0)
        n = p14 / (p10 + 1.0);
    return std::isfinite(n) && n > 1e-6 ? n : 0.1;
}

}  // namespace

TileLayout tileLayout(int maxLights) {
    TileLayout t;
    t.tilesPerRow = int(std::ceil(std::sqrt(double(maxLights))));
    t.tileSize = std::min(kMaxTileSize, kMaxAtlasSide / t.tilesPerRow);
    return t;
}

bool sunMapCamera(const fk_frame& f, const fk_light& l, float viewProjection[16]) {
    // The eye: view = [R | t] is rigid, so the eye is -R^T t.
    double eye[3];
    for (int i = 0; i < 3; ++i)
        eye[i] = -(double(f.view[i * 4 + 0]) * f.view[12] + double(f.view[i * 4 + 1]) * f.view[13] +
                   double(f.view[i * 4 + 2]) * f.view[14]);
    double axis[3], half = 0, farPlane = 1e7;
    if (l.type == FK_LIGHT_POINT) {
        double d[3] = {l.position[0] - eye[0], l.position[1] - eye[1], l.position[2] - eye[2]};
        const double dist = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (dist <= l.radius) return false;  // inside the light: the reduction says 1
        for (int k = 0; k < 3; ++k) axis[k] = d[k] / dist;
        half = std::asin(double(l.radius) / dist);
        // Only what lies before the light hides it (kNearSide of light_view.glsl).
        farPlane = (dist - l.radius) * 0.999;
    } else {
        const double dl = std::sqrt(double(l.direction[0]) * l.direction[0] +
                                    double(l.direction[1]) * l.direction[1] +
                                    double(l.direction[2]) * l.direction[2]);
        for (int k = 0; k < 3; ++k) axis[k] = l.direction[k] / dl;
        half = double(l.radius) * 3.14159265358979323846 / 180.0;
    }
    const std::array<float, 16> vp =
        coneCamera(eye, axis, half, nearPlaneOf(f), farPlane, f.depth_convention);
    std::copy(vp.begin(), vp.end(), viewProjection);
    return true;
}

Result<SunMapAtlas> SunMapAtlas::create(int maxLights) {
    SunMapAtlas a;
    const TileLayout layout = tileLayout(maxLights);
    a.m_tilesPerRow = layout.tilesPerRow;
    a.m_tileSize = layout.tileSize;
    const int side = a.m_tilesPerRow * a.m_tileSize;
    a.m_atlas = gl::makeTexture2D(GL_RGBA8, side, side);
    auto target = gl::makeFramebuffer(a.m_atlas.get());
    if (!target) return target.error();
    a.m_target = std::move(*target);
    return a;
}

void SunMapAtlas::draw(int view, const fk_frame& f, const fk_light* lights, const int* tileOf,
                       int count, fk_occluder_callback occluders, void* user) const {
    const float white[4] = {1, 1, 1, 1};
    glClearNamedFramebufferfv(m_target.get(), GL_COLOR, 0, white);
    for (int i = 0; i < count; ++i) {
        const int at = tileOf[i];
        float vp[16];
        if (at < 0 || !sunMapCamera(f, lights[i], vp)) continue;  // on the depth, or inside it
        const int tile[4] = {(at % m_tilesPerRow) * m_tileSize, (at / m_tilesPerRow) * m_tileSize,
                             m_tileSize, m_tileSize};
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_target.get());
        glViewport(tile[0], tile[1], tile[2], tile[3]);
        occluders(user, view, i, vp, m_target.get(), tile);
    }
}

}  // namespace flarekit::engine
