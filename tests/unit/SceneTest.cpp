// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "flarekit/Scene.h"

using namespace flarekit;

namespace {
const std::string kHead = R"({"image": {"width": 640, "height": 360},
  "camera": {"position": [0, 1.7, 0], "look_at": [0, 5, -20]},
  "sun": {"direction": [0.2, 0.3, -1]},)";

std::string errorOf(const std::string& objects) {
    auto r = parseScene(kHead + R"("objects": )" + objects + "}", "scene.json");
    return r.ok() ? "(ok)" : r.error().message;
}
}  // namespace

TEST(Scene, ContractExampleLoads) {
    auto s = loadScene(std::string(FLAREKIT_SAMPLES) + "/scenes/contract-example.json");
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(s->width, 640);
    EXPECT_EQ(s->spheres.size(), 1u);
    EXPECT_EQ(s->boxes.size(), 1u);
    EXPECT_EQ(s->triangles.size(), 1u);
    EXPECT_NEAR(length(s->sun.direction), 1.0, 1e-12);  // normalised
    EXPECT_DOUBLE_EQ(s->camera.fovYDeg, 60);
}

TEST(Scene, ErrorsNameTheField) {
    EXPECT_EQ(
        errorOf(
            R"([{"type":"box","min":[0,0,0],"max":[1,1,1]},{"type":"box","min":[0,0,0],"max":[1,1,1]},
        {"type":"box","min":[0,0,0],"max":[1,1,1]},{"type":"box","min":[0,0,0],"max":[1,1,1]},
        {"type":"sphere","center":[0,0,0],"radius":-1}])"),
        "scene.json: objects[4].radius: expected a positive number, got -1");
    EXPECT_EQ(errorOf(R"([{"type":"sphere","center":[0,0],"radius":1}])"),
              "scene.json: objects[0].center: expected an array of 3 numbers, got [0,0]");
    EXPECT_EQ(
        errorOf(R"([{"type":"cone"}])"),
        R"(scene.json: objects[0].type: expected "sphere", "box" or "triangles", got "cone")");
    EXPECT_EQ(errorOf(R"([{"type":"box","min":[0,0,0],"max":[1,0,1]}])"),
              "scene.json: objects[0].max: expected every component greater than min's");
    EXPECT_EQ(errorOf(R"([{"type":"triangles","vertices":[[0,0,0],[1,0,0]]}])"),
              "scene.json: objects[0].vertices: expected an array of 3N vertices (N >= 1), got "
              "[[0,0,0],[1,0,0]]");
    EXPECT_EQ(errorOf(R"([{"type":"sphere","center":[0,0,0],"radius":1,"colour":[1,0,0]}])"),
              "scene.json: objects[0].colour: unknown key (expected one of: type, center, radius, "
              "color, opacity)");
    EXPECT_EQ(errorOf("[]"), "(ok)");
}

TEST(Scene, CameraAndSunAreChecked) {
    // A valid scene; each case breaks one field of it (no value: the field is removed).
    const nlohmann::json valid = nlohmann::json::parse(
        R"({"image": {"width": 10, "height": 10},
            "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1]},
            "sun": {"direction": [0, 0, -1]}})");
    const struct {
        const char* field;
        const char* value;
        const char* error;
    } cases[] = {
        {"/image", nullptr, "s.json: image: missing; expected an object"},
        {"/image/width", "0", "s.json: image.width: expected an integer in [1, 32768], got 0"},
        {"/camera/look_at", "[0, 0, 0]",
         "s.json: camera.look_at: expected a point different from camera.position"},
        {"/sun/direction", "[0, 0, 0]", "s.json: sun.direction: expected a non-zero direction"},
        {"/camera/look_at", "[0, 1, 0]",
         "s.json: camera.up: expected a direction not parallel to the view direction"},
    };
    const auto errorIn = [](const std::string& text) {
        auto r = parseScene(text, "s.json");
        return r.ok() ? "(ok)" : r.error().message;
    };
    EXPECT_EQ(errorIn(valid.dump()), "(ok)");
    for (const auto& c : cases) {
        nlohmann::json scene = valid;
        const nlohmann::json::json_pointer field(c.field);
        if (c.value)
            scene[field] = nlohmann::json::parse(c.value);
        else
            scene[field.parent_pointer()].erase(field.back());
        EXPECT_EQ(errorIn(scene.dump()), c.error) << c.field;
    }
    EXPECT_EQ(errorIn("{").rfind("s.json: invalid JSON: parse error", 0), 0u);
}
