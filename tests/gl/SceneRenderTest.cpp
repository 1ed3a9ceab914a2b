// SPDX-License-Identifier: Apache-2.0
// The GL scene renderer against the scene's own geometry: the sun disc where the camera maths
// puts it, objects where they project, and the flare scaled by coverage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "GlTestContext.h"
#include "flarekit/gl/Render.h"
#include "scene/CameraMath.h"

using namespace flarekit;

namespace {
void needContext() {
    test::glContext();
}

Scene openSky() {
    Scene s;
    s.width = 320;
    s.height = 180;
    s.camera.position = {0, 1.7, 0};
    s.camera.lookAt = {0, 5, -20};
    s.sun.direction = normalize(Vec3{0.2, 0.3, -1});
    s.sun.angularRadiusDeg = 2.0;
    return s;
}
}  // namespace

TEST(SceneRender, SunDiscIsDrawnAtItsProjectionWithColourTimesIntensity) {
    needContext();
    const Scene s = openSky();
    auto frame = renderScene(s);
    ASSERT_TRUE(frame.ok()) << frame.error().message;
    Point sun;
    ASSERT_TRUE(projectDirection(s, s.sun.direction, sun));
    const Rgba& p = frame->at(int(sun.x), int(sun.y));
    // RGBA16F keeps 11 significant bits: one part in 2048.
    const double k = s.sun.intensity;
    EXPECT_NEAR(p.r, k * 1.0, k / 1024);
    EXPECT_NEAR(p.g, k * 0.95, k / 1024);
    EXPECT_NEAR(p.b, k * 0.85, k / 1024);
    const Rgba& sky = frame->at(int(sun.x) + 40, int(sun.y));  // 40 px is ~10 deg away
    EXPECT_LT(sky.r, 2.f);
}

TEST(SceneRender, SphereCoversItsProjectionAndNothingElse) {
    needContext();
    Scene s = openSky();
    const Scene empty = s;
    const Vec3 centre{-3, 3, -25};
    s.spheres.push_back({centre, 1.5, {0.8, 0.1, 0.1}});
    auto withSphere = renderScene(s), without = renderScene(empty);
    ASSERT_TRUE(withSphere.ok() && without.ok());
    Point c;
    ASSERT_TRUE(projectPoint(s, centre, c));
    const Rgba& inside = withSphere->at(int(c.x), int(c.y));
    EXPECT_GT(inside.r, 2 * inside.b);  // red albedo, not sky blue
    // The sphere's angular radius asin(1.5 / d) in pixels, with a 3-pixel margin either side.
    const double d = length(centre - s.camera.position), rad = std::asin(1.5 / d);
    const double pxPerRad = 180 / (2 * std::tan(30 * M_PI / 180));
    const int r = int(rad * pxPerRad);
    const Rgba& outside = withSphere->at(int(c.x) + r + 3, int(c.y));
    const Rgba& outsideSky = without->at(int(c.x) + r + 3, int(c.y));
    EXPECT_FLOAT_EQ(outside.b, outsideSky.b);
    const Rgba& rim = withSphere->at(int(c.x) + r - 3, int(c.y));
    EXPECT_NE(rim.b, without->at(int(c.x) + r - 3, int(c.y)).b);
}

TEST(SceneRender, ObjectsDrawAfterAnEmptySceneInTheSameContext) {
    // Regression: an empty scene left depth writes off, so the next frame's depth clear did
    // nothing and every object failed the depth test.
    needContext();
    ASSERT_TRUE(renderScene(openSky()).ok());
    Scene s = openSky();
    const Vec3 centre{0, 3, -20};
    s.spheres.push_back({centre, 1.5, {0.8, 0.1, 0.1}});
    auto frame = renderScene(s);
    ASSERT_TRUE(frame.ok());
    Point c;
    ASSERT_TRUE(projectPoint(s, centre, c));
    const Rgba& p = frame->at(int(c.x), int(c.y));
    EXPECT_GT(p.r, 2 * p.b);
}

TEST(SceneRender, FlareScalesWithCoverage) {
    needContext();
    const Scene s = openSky();
    auto base = renderScene(s);
    ASSERT_TRUE(base.ok());
    auto preset = loadPreset("tanczos-classic");
    ASSERT_TRUE(preset.ok());
    Image none = *base, half = *base, full = *base;
    EXPECT_EQ(addSunFlare(none, s, *preset, 0.0).flareIntensity, 0.f);
    addSunFlare(half, s, *preset, 0.5);
    const FlaredFrame f = addSunFlare(full, s, *preset, 1.0);
    EXPECT_TRUE(f.sunInFront);
    double added0 = 0, addedHalf = 0, addedFull = 0;
    for (std::size_t i = 0; i < base->pixelCount() * 4; ++i) {
        added0 += none.data()[i] - base->data()[i];
        addedHalf += half.data()[i] - base->data()[i];
        addedFull += full.data()[i] - base->data()[i];
    }
    EXPECT_EQ(added0, 0.0);
    EXPECT_GT(addedFull, 1000.0);
    EXPECT_NEAR(addedHalf / addedFull, 0.5, 1e-4);
}

TEST(SceneRender, SunBehindTheCameraGivesNoFlare) {
    needContext();
    Scene s = openSky();
    s.sun.direction = {0, 0.3, 1};
    auto frame = renderScene(s);
    ASSERT_TRUE(frame.ok());
    const Image before = *frame;
    auto preset = loadPreset("subtle");
    EXPECT_FALSE(addSunFlare(*frame, s, *preset, 1.0).sunInFront);
    EXPECT_EQ(0, std::memcmp(before.data(), frame->data(), before.pixelCount() * sizeof(Rgba)));
}

TEST(SceneRender, PersistentRendererMatchesOneShotFramesAfterACameraMove) {
    needContext();
    Scene s = openSky();
    s.spheres.push_back({{-3, 3, -25}, 1.5, {0.8, 0.1, 0.1}});
    s.boxes.push_back({{2, 0, -30}, {4, 5, -28}, {0.4, 0.4, 0.4}});
    auto renderer = SceneRenderer::create(s);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;
    ASSERT_TRUE(renderer->draw(s).ok());
    Scene moved = s;
    moved.camera.position = {1, 2, 3};
    moved.camera.lookAt = {-1, 3, -25};
    Scene cameraOnly = moved;  // draw() takes camera and sun only: objects stay uploaded
    cameraOnly.spheres.clear();
    cameraOnly.boxes.clear();
    ASSERT_TRUE(renderer->draw(cameraOnly).ok());
    auto kept = renderer->readColor();
    auto fresh = renderScene(moved);
    ASSERT_TRUE(kept.ok() && fresh.ok());
    EXPECT_EQ(0, std::memcmp(kept->data(), fresh->data(), kept->pixelCount() * sizeof(Rgba)));
}

TEST(SceneRender, BoxCastsItsShadowWhereTheSunRayPredicts) {
    needContext();
    Scene s = openSky();
    s.camera.position = {0, 6, 0};
    s.camera.lookAt = {0, 0, -20};
    s.sun.direction = normalize(Vec3{0.3, 0.8, -0.5});
    const Vec3 grey{0.5, 0.5, 0.5};
    s.boxes.push_back({{-50, -1, -80}, {50, 0, 10}, grey});  // ground
    const Vec3 blocker{-2, 3, -22};
    s.boxes.push_back({blocker - Vec3{1, 0.2, 1}, blocker + Vec3{1, 0.2, 1}, grey});
    // The ground point whose ray to the sun passes through the blocker's centre, and one 5 m
    // beside it that nothing shades.
    const Vec3 shadowed = blocker - s.sun.direction * (blocker.y / s.sun.direction.y);
    const Vec3 lit = shadowed + Vec3{-5, 0, 0};
    Point ps, pl;
    ASSERT_TRUE(projectPoint(s, shadowed, ps) && projectPoint(s, lit, pl));
    auto frame = renderScene(s);
    RenderOptions noShadows;
    noShadows.shadows = false;
    auto flat = renderScene(s, noShadows);
    ASSERT_TRUE(frame.ok() && flat.ok());
    // Lambert: albedo x (irradiance x cos + ambient), irradiance = radiance x the disc's solid
    // angle pi sin^2(r); in shadow the sun term is gone. Red channel, sun colour r = 1.
    const double sinR = std::sin(s.sun.angularRadiusDeg * 3.14159265358979323846 / 180.0);
    const double sunTerm =
        0.5 * s.sun.intensity * 3.14159265358979323846 * sinR * sinR * s.sun.direction.y;
    const float inShadow = frame->at(int(ps.x), int(ps.y)).r,
                inSun = frame->at(int(pl.x), int(pl.y)).r;
    EXPECT_NEAR(inSun - inShadow, sunTerm, 0.02 * sunTerm);
    EXPECT_NEAR(flat->at(int(ps.x), int(ps.y)).r, inSun, 0.01f * inSun);
}

TEST(SceneRender, MsaaSmoothsEdgesAndKeepsInteriors) {
    needContext();
    Scene s = openSky();
    const Vec3 centre{0, 3, -20};
    s.spheres.push_back({centre, 2.0, {0.8, 0.1, 0.1}});
    RenderOptions msaa;
    msaa.msaaSamples = 4;
    auto aliased = renderScene(s), smooth = renderScene(s, msaa);
    ASSERT_TRUE(aliased.ok() && smooth.ok()) << (smooth.ok() ? "" : smooth.error().message);
    Point c;
    ASSERT_TRUE(projectPoint(s, centre, c));
    EXPECT_NEAR(smooth->at(int(c.x), int(c.y)).r, aliased->at(int(c.x), int(c.y)).r, 1e-3f);
    // Along the row through the centre, the 1x frame only has sky or sphere values; 4x MSAA has
    // at least one pixel part way between at the silhouette.
    const int y = int(c.y);
    const float skyB = aliased->at(1, y).b, sphereB = aliased->at(int(c.x), y).b;
    int between = 0;
    for (int x = 0; x < s.width; ++x) {
        const float b = smooth->at(x, y).b;
        if (b > std::min(skyB, sphereB) + 0.02f && b < std::max(skyB, sphereB) - 0.02f) ++between;
    }
    EXPECT_GE(between, 2);
}

TEST(SceneRender, BadRendererSettingsAreErrors) {
    needContext();
    RenderOptions bad;
    bad.msaaSamples = 3;
    EXPECT_FALSE(SceneRenderer::create(openSky(), bad).ok());
    auto renderer = SceneRenderer::create(openSky());
    ASSERT_TRUE(renderer.ok());
    Scene other = openSky();
    other.width = 64;
    const Status s = renderer->setGeometry(other);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("64x180"), std::string::npos) << s.error().message;
}
