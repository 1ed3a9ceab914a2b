// SPDX-License-Identifier: Apache-2.0
// Many lights and translucent objects in the Scene JSON and the ray-cast truth, against closed
// forms: a point light's cone is the one its sphere subtends, a ray reaches the light unless
// an object lies between, and a ray through an object of opacity a keeps 1 - a of the light.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flarekit/Visibility.h"

using namespace flarekit;

namespace {

constexpr double kPi = std::numbers::pi;
// The ground truth's bound at its default 128^2 rays per light (RaycastTest.cpp).
constexpr double kTolerance = 0.005;

Scene lookingDownMinusZ() {
    Scene s;
    s.camera.position = {0, 0, 0};
    s.camera.lookAt = {0, 0, -1};
    s.camera.up = {0, 1, 0};
    return s;
}

SceneLight pointLight(Vec3 position, double radius) {
    SceneLight l;
    l.type = LightType::Point;
    l.position = position;
    l.radius = radius;
    return l;
}

VisibilityResult raycast(const Scene& s) {
    auto r = raycastVisibility(s);
    EXPECT_TRUE(r.ok()) << (r ? "" : r.error().message);
    return r ? *r : VisibilityResult{};
}

}  // namespace

TEST(Lights, PointLightInFrontOfAWallIsSeenAndOneBehindItIsNot) {
    Scene s = lookingDownMinusZ();
    s.boxes.push_back({{-5, -5, -21}, {5, 5, -20}});   // a wall 20 m ahead
    s.lights.push_back(pointLight({0, 0, -10}, 0.2));  // in front of it
    s.lights.push_back(pointLight({0, 0, -30}, 0.2));  // behind it
    s.lights.push_back(pointLight({0, 0, 10}, 0.2));   // behind the camera, nothing between
    const VisibilityResult r = raycast(s);
    ASSERT_EQ(r.lights.size(), 3u);
    EXPECT_EQ(r.lights[0].coverage, 1.0);
    EXPECT_EQ(r.lights[1].coverage, 0.0);
    EXPECT_EQ(r.lights[2].coverage, 1.0);
    EXPECT_EQ(r.lights[0].inFrame, 1.0);
    EXPECT_EQ(r.lights[2].inFrame, 0.0);
    EXPECT_EQ(r.coverage, r.lights[0].coverage);  // the top level is the first light
}

TEST(Lights, ConcentricSphereHidesTheClosedFormShareOfAPointLight) {
    // A light of angular radius alpha behind an occluding ball of angular radius beta < alpha
    // on the same axis: the visible share is 1 - (1 - cos beta) / (1 - cos alpha), since
    // coverage is uniform over solid angle.
    Scene s = lookingDownMinusZ();
    const double lightDistance = 40, lightRadius = 2;
    const double alpha = std::asin(lightRadius / lightDistance);
    const double beta = 0.6 * alpha, ballDistance = 10;
    s.spheres.push_back({{0, 0, -ballDistance}, ballDistance * std::sin(beta)});
    s.lights.push_back(pointLight({0, 0, -lightDistance}, lightRadius));
    const double expected = 1 - (1 - std::cos(beta)) / (1 - std::cos(alpha));
    EXPECT_NEAR(raycast(s).lights[0].coverage, expected, kTolerance);
}

TEST(Lights, TranslucentObjectsKeepTheProductOfTheirTransmittances) {
    Scene s = lookingDownMinusZ();
    s.lights.push_back(pointLight({0, 0, -30}, 0.5));
    s.boxes.push_back({{-5, -5, -11}, {5, 5, -10}, {0.5, 0.5, 0.5}, 0.3});  // glass pane
    EXPECT_NEAR(raycast(s).lights[0].coverage, 0.7, 1e-12);
    s.spheres.push_back({{0, 0, -20}, 3, {0.5, 0.5, 0.5}, 0.5});  // crossed twice, counted once
    EXPECT_NEAR(raycast(s).lights[0].coverage, 0.35, 1e-12);
    Triangle fogCard{{-9, -9, -5}, {9, -9, -5}, {0, 9, -5}, {1, 1, 1}, 0.2};
    s.triangles.push_back(fogCard);
    EXPECT_NEAR(raycast(s).lights[0].coverage, 0.28, 1e-12);
    s.boxes.push_back({{-5, -5, -41}, {5, 5, -40}});  // opaque, but behind the light
    EXPECT_NEAR(raycast(s).lights[0].coverage, 0.28, 1e-12);
}

TEST(Lights, DirectionalLightsBehaveLikeTheSun) {
    Scene s = lookingDownMinusZ();
    s.sun.direction = normalize(Vec3{0.1, 0.05, -1});
    s.sun.angularRadiusDeg = 1;
    s.spheres.push_back({{0, 0, -50}, 2});  // over the view axis, off the sun
    const double sunAlone = raycast(s).coverage;
    s.lights = {lightFromSun(s.sun)};
    SceneLight ahead = lightFromSun(s.sun);
    ahead.direction = {0, 0, -1};
    s.lights.push_back(ahead);
    const VisibilityResult r = raycast(s);
    EXPECT_EQ(r.lights[0].coverage, sunAlone);
    EXPECT_EQ(r.lights[1].coverage, 0.0);
}

TEST(Lights, CameraInsideASphereLightSeesAllOfIt) {
    Scene s = lookingDownMinusZ();
    s.lights.push_back(pointLight({0, 0, 0.1}, 1));
    s.boxes.push_back({{-5, -5, -11}, {5, 5, -10}});
    EXPECT_EQ(raycast(s).lights[0].coverage, 1.0);
}

TEST(LightsJson, LightsArrayWithAndWithoutSun) {
    const std::string head =
        R"({"image": {"width": 64, "height": 36}, "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1]}, )";
    auto onlyLights = parseScene(head + R"("lights": [
        {"type": "point", "position": [1, 2, -10], "radius": 0.3, "intensity": 5, "preset": "subtle"},
        {"type": "directional", "direction": [0, 0, -2], "angular_radius_deg": 0.5}]})",
                                 "s.json");
    ASSERT_TRUE(onlyLights.ok()) << onlyLights.error().message;
    ASSERT_EQ(onlyLights->lights.size(), 2u);
    EXPECT_EQ(onlyLights->lights[0].type, LightType::Point);
    EXPECT_EQ(onlyLights->lights[0].preset, "subtle");
    EXPECT_EQ(onlyLights->lights[0].radius, 0.3);
    EXPECT_EQ(onlyLights->lights[1].direction.z, -1.0);          // normalised
    EXPECT_EQ(onlyLights->lights[1].preset, "tanczos-classic");  // the default
    // `sun` mirrors the first directional light.
    EXPECT_EQ(onlyLights->sun.angularRadiusDeg, 0.5);
    EXPECT_EQ(onlyLights->sun.intensity, 50.0);

    auto both = parseScene(head + R"("sun": {"direction": [0, 1, -1]}, "lights": [
        {"type": "point", "position": [0, 0, -5]}]})",
                           "s.json");
    ASSERT_TRUE(both.ok()) << both.error().message;
    ASSERT_EQ(both->lights.size(), 2u);
    EXPECT_EQ(both->lights[0].type, LightType::Directional);  // the sun comes first
    EXPECT_NEAR(both->lights[0].direction.y, std::sqrt(0.5), 1e-12);

    auto pointsOnly =
        parseScene(head + R"("lights": [{"type": "point", "position": [0, 0, -5]}]})", "s.json");
    ASSERT_TRUE(pointsOnly.ok());
    EXPECT_EQ(pointsOnly->sun.intensity, 0.0);  // no directional light: a dark sun

    auto noSun = parseScene(head + R"("sun": {"direction": [0, 1, -1]}})", "s.json");
    ASSERT_TRUE(noSun.ok());
    EXPECT_TRUE(noSun->lights.empty());
    EXPECT_EQ(sceneLights(*noSun).size(), 1u);
}

TEST(LightsJson, BadLightsAndOpacitiesNameTheField) {
    const std::string head =
        R"({"image": {"width": 64, "height": 36}, "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1]}, )";
    const auto error = [&](const std::string& rest) {
        auto s = parseScene(head + rest, "s.json");
        return s.ok() ? std::string("parsed") : s.error().message;
    };
    EXPECT_EQ(error("\"objects\": []}"),
              "s.json: sun: missing; expected an object (or a \"lights\" array)");
    EXPECT_NE(error(R"("lights": [{"type": "point", "position": [0, 0, -5], "radius": -1}]})")
                  .find("s.json: lights[0].radius: expected"),
              std::string::npos);
    EXPECT_NE(error(R"("lights": [{"type": "spot", "position": [0, 0, -5]}]})")
                  .find("lights[0].type: expected \"directional\" or \"point\""),
              std::string::npos);
    EXPECT_NE(error(R"("lights": [{"type": "directional", "direction": [0, 0, 0]}]})")
                  .find("lights[0].direction: expected a non-zero direction"),
              std::string::npos);
    EXPECT_NE(error(R"("lights": [{"type": "point"}]})").find("lights[0].position"),
              std::string::npos);
    EXPECT_NE(error(R"("lights": []})").find("lights: expected a non-empty array"),
              std::string::npos);
    EXPECT_NE(error(R"("lights": [{"type": "point", "position": [0, 0, -5], "preset": 3}]})")
                  .find("lights[0].preset: expected a preset name"),
              std::string::npos);
    EXPECT_NE(
        error(
            R"("sun": {"direction": [0, 0, -1]}, "objects": [{"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "opacity": 1.5}]})")
            .find("objects[0].opacity: expected"),
        std::string::npos);
    auto glass = parseScene(
        head +
            R"("sun": {"direction": [0, 0, -1]}, "objects": [{"type": "triangles", "opacity": 0.25, "vertices": [[0, 0, -1], [1, 0, -1], [0, 1, -1]]}]})",
        "s.json");
    ASSERT_TRUE(glass.ok()) << glass.error().message;
    EXPECT_EQ(glass->triangles[0].opacity, 0.25);
}
