// SPDX-License-Identifier: Apache-2.0
// Scene JSON (the docs/architecture.md contract) with full validation: every error names the file
// and the field, and says what was expected.
#include <cmath>
#include <numbers>

#include "core/ParamJson.h"
#include "flarekit/Image.h"
#include "flarekit/ParamText.h"
#include "flarekit/Scene.h"

namespace flarekit {

using json = nlohmann::json;

namespace {

//! Largest accepted scene triangle count: 1 million (2^20). The JSON tree of a triangle (3
//! vertex arrays of 3 numbers) costs ~600 bytes while it is parsed, so the limit keeps a scene
//! under ~0.6 GB and ~4 s of parsing; bigger meshes belong in an engine (the C API measures
//! any depth buffer).
constexpr std::size_t kMaxTriangles = std::size_t(1) << 20;
//! The parse stops past this many JSON events (keys, values, ends: 15 per triangle), so an
//! oversized scene is refused while it is read, not after: every triangle allowed, every light
//! (~20 each) and a million spheres or boxes besides.
constexpr std::size_t kMaxSceneJsonValues =
    16 * kMaxTriangles + 20 * kMaxSceneLights + (std::size_t(16) << 20);
//! Scene files above this size are refused unread: 1M triangles written with 17 digits per
//! coordinate take ~200 MB.
constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t(256) << 20;

#define FK_TRY(expr) \
    if (auto fk_err = (expr)) return *fk_err

std::optional<Error> readTriangles(const json& o, const JsonPlace& at, Scene& s) {
    TrianglesColor c;
    FK_TRY(readParams<TrianglesColor>(o, kTrianglesParams, c, at, {"type", "vertices"}));
    const auto v = o.find("vertices");
    if (v == o.end() || !v->is_array() || v->empty() || v->size() % 3 != 0) {
        return (at / "vertices")
            .fail("expected an array of 3N vertices (N >= 1), got " +
                  (v == o.end() ? std::string("nothing") : jsonExcerpt(*v)));
    }
    if (s.triangles.size() + v->size() / 3 > kMaxTriangles) {
        return (at / "vertices")
            .fail("expected at most " + std::to_string(kMaxTriangles) + " triangles in a scene");
    }
    const Param<Triangle> point =
        param<&Triangle::a>("vertex", kSceneAnyCoordinate, kParamUnbounded, "m", "");
    for (std::size_t k = 0; k < v->size(); k += 3) {
        Triangle tri;
        tri.color = c.color;
        tri.opacity = c.opacity;
        for (std::size_t j = 0; j < 3; ++j) {
            auto p = readParamValue(point, (*v)[k + j], (at / "vertices").index(k + j));
            if (!p) return p.error();
            (j == 0 ? tri.a : j == 1 ? tri.b : tri.c) = p->vector;
        }
        s.triangles.push_back(tri);
    }
    return std::nullopt;
}

std::optional<Error> readObject(const json& o, const JsonPlace& at, Scene& s) {
    if (!o.is_object()) return at.fail("expected an object, got " + jsonExcerpt(o));
    const auto type = o.find("type");
    const std::string t = type != o.end() && type->is_string() ? type->get<std::string>() : "";
    if (t == "sphere") {
        Sphere sp;
        FK_TRY(readParams<Sphere>(o, kSphereParams, sp, at, {"type"}));
        s.spheres.push_back(sp);
    } else if (t == "box") {
        Box b;
        FK_TRY(readParams<Box>(o, kBoxParams, b, at, {"type"}));
        if (!(b.min.x < b.max.x && b.min.y < b.max.y && b.min.z < b.max.z)) {
            return (at / "max").fail("expected every component greater than min's");
        }
        s.boxes.push_back(b);
    } else if (t == "triangles") {
        FK_TRY(readTriangles(o, at, s));
    } else {
        return (at / "type")
            .fail(R"(expected "sphere", "box" or "triangles", got )" +
                  (type == o.end() ? std::string("nothing") : jsonExcerpt(*type)));
    }
    return std::nullopt;
}

std::optional<Error> readLight(const json& o, const JsonPlace& at, Scene& s) {
    if (!o.is_object()) return at.fail("expected an object, got " + jsonExcerpt(o));
    const auto type = o.find("type");
    const std::string t = type != o.end() && type->is_string() ? type->get<std::string>() : "";
    SceneLight light;
    if (t == "directional") {
        FK_TRY(readParams<SceneLight>(o, kDirectionalLightParams, light, at, {"type", "preset"}));
        if (length(light.direction) < 1e-12)
            return (at / "direction").fail("expected a non-zero direction");
        light.direction = normalize(light.direction);
    } else if (t == "point") {
        light.type = LightType::Point;
        FK_TRY(readParams<SceneLight>(o, kPointLightParams, light, at, {"type", "preset"}));
    } else {
        return (at / "type")
            .fail(R"(expected "directional" or "point", got )" +
                  (type == o.end() ? std::string("nothing") : jsonExcerpt(*type)));
    }
    if (const auto preset = o.find("preset"); preset != o.end()) {
        if (!preset->is_string())
            return (at / "preset")
                .fail("expected a preset name or path, got " + jsonExcerpt(*preset));
        light.preset = preset->get<std::string>();
    }
    s.lights.push_back(light);
    return std::nullopt;
}

//! "sun" and "lights" into Scene::lights (the sun first) and Scene::sun (the first directional
//! light, or a dark sun when there is none).
std::optional<Error> readLights(const json& doc, const JsonPlace& top, Scene& s) {
    const auto lights = doc.find("lights");
    if (doc.contains("sun")) {
        FK_TRY(readParams<SceneSun>(doc["sun"], kSceneSunParams, s.sun, top / "sun"));
        if (lights == doc.end()) return std::nullopt;
        if (length(s.sun.direction) < 1e-12)
            return (top / "sun" / "direction").fail("expected a non-zero direction");
        s.sun.direction = normalize(s.sun.direction);
        s.lights.push_back(lightFromSun(s.sun));
    } else if (lights == doc.end()) {
        return (top / "sun").fail("missing; expected an object (or a \"lights\" array)");
    }
    if (!lights->is_array() || lights->empty())
        return (top / "lights").fail("expected a non-empty array, got " + jsonExcerpt(*lights));
    if (lights->size() + s.lights.size() > kMaxSceneLights) {
        return (top / "lights")
            .fail("expected at most " + std::to_string(kMaxSceneLights) + " lights");
    }
    for (std::size_t i = 0; i < lights->size(); ++i)
        FK_TRY(readLight((*lights)[i], JsonPlace(top.source(), "lights").index(i), s));
    if (!doc.contains("sun")) {
        s.sun.intensity = 0;  // no directional light: a sun nobody sees
        for (const SceneLight& l : s.lights) {
            if (l.type != LightType::Directional) continue;
            s.sun = lightAsSun(l, s.camera);
            break;
        }
    }
    return std::nullopt;
}

Result<Scene> readScene(const json& doc, const JsonPlace& top) {
    Scene s;
    if (!doc.is_object()) return top.fail("expected an object, got " + jsonExcerpt(doc));
    for (const auto& [key, value] : doc.items()) {
        if (key != "image" && key != "camera" && key != "sun" && key != "lights" &&
            key != "objects" && key != "ground")
            return (top / key).fail(
                "unknown key (expected one of: image, camera, sun, lights, ground, objects)");
    }
    for (const char* section : {"image", "camera"}) {
        if (!doc.contains(section)) return (top / section).fail("missing; expected an object");
    }
    FK_TRY(readParams<Scene>(doc["image"], kSceneImageParams, s, top / "image"));
    FK_TRY(readParams<SceneCamera>(doc["camera"], kSceneCameraParams, s.camera, top / "camera"));
    FK_TRY(readLights(doc, top, s));
    if (const auto ground = doc.find("ground"); ground != doc.end()) {
        Ground g;
        FK_TRY(readParams<Ground>(*ground, kGroundParams, g, top / "ground"));
        s.ground = g;
    }
    const auto objects = doc.find("objects");
    if (objects == doc.end()) return s;
    if (!objects->is_array())
        return (top / "objects").fail("expected an array, got " + jsonExcerpt(*objects));
    for (std::size_t i = 0; i < objects->size(); ++i) {
        FK_TRY(readObject((*objects)[i], JsonPlace(top.source(), "objects").index(i), s));
    }
    return s;
}

//! What no single field can say, in the order the reader used to check it.
Status checkAcrossFields(const Scene& s) {
    if (s.camera.farPlane <= s.camera.nearPlane)
        return invalidInput("camera.far: expected a number greater than camera.near");
    const Vec3 view = s.camera.lookAt - s.camera.position;
    if (length(view) < 1e-12)
        return invalidInput("camera.look_at: expected a point different from camera.position");
    if (length(cross(normalize(view), s.camera.up)) < 1e-9) {
        return invalidInput("camera.up: expected a direction not parallel to the view direction");
    }
    if (length(s.sun.direction) < 1e-12)
        return invalidInput("sun.direction: expected a non-zero direction");
    if (s.lights.size() > kMaxSceneLights) {
        return invalidInput("lights: expected at most " + std::to_string(kMaxSceneLights) +
                            " lights");
    }
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        const SceneLight& l = s.lights[i];
        const std::string at = "lights[" + std::to_string(i) + "].";
        const bool point = l.type == LightType::Point;
        if (!point && l.type != LightType::Directional)
            return invalidInput(at + "type: expected directional or point");
        if (Status st = point ? validateParams<SceneLight>(l, kPointLightParams, at)
                              : validateParams<SceneLight>(l, kDirectionalLightParams, at);
            !st)
            return st;
        if (!point && length(l.direction) < 1e-12)
            return invalidInput(at + "direction: expected a non-zero direction");
    }
    return Ok{};
}

#undef FK_TRY

}  // namespace

Status validateScene(const Scene& s) {
    if (Status st = validateParams<Scene>(s, kSceneImageParams, "image."); !st) return st;
    if (Status st = validateParams<SceneCamera>(s.camera, kSceneCameraParams, "camera."); !st)
        return st;
    if (Status st = validateParams<SceneSun>(s.sun, kSceneSunParams, "sun."); !st) return st;
    if (Status st = checkAcrossFields(s); !st) return st;
    for (std::size_t i = 0; i < s.spheres.size(); ++i) {
        const std::string at = "spheres[" + std::to_string(i) + "].";
        if (Status st = validateParams<Sphere>(s.spheres[i], kSphereParams, at); !st) return st;
    }
    for (std::size_t i = 0; i < s.boxes.size(); ++i) {
        const std::string at = "boxes[" + std::to_string(i) + "].";
        if (Status st = validateParams<Box>(s.boxes[i], kBoxParams, at); !st) return st;
        const Box& b = s.boxes[i];
        if (!(b.min.x < b.max.x && b.min.y < b.max.y && b.min.z < b.max.z)) {
            return invalidInput(at + "max: expected every component greater than min's");
        }
    }
    if (s.triangles.size() > kMaxTriangles) {
        return invalidInput("triangles: expected at most " + std::to_string(kMaxTriangles) +
                            " triangles in a scene");
    }
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
        if (!(s.triangles[i].opacity >= 0 && s.triangles[i].opacity <= 1)) {
            return invalidInput("triangles[" + std::to_string(i) +
                                "].opacity: expected a number in [0, 1]");
        }
    }
    if (s.ground) {
        if (Status st = validateParams<Ground>(*s.ground, kGroundParams, "ground."); !st) return st;
    }
    return Ok{};
}

SceneLight lightFromSun(const SceneSun& sun) {
    SceneLight l;
    l.type = LightType::Directional;
    l.direction = sun.direction;
    l.angularRadiusDeg = sun.angularRadiusDeg;
    l.color = sun.color;
    l.intensity = sun.intensity;
    return l;
}

SceneSun lightAsSun(const SceneLight& light, const SceneCamera& camera) {
    SceneSun sun{light.direction, light.angularRadiusDeg, light.color, light.intensity};
    if (light.type != LightType::Point) return sun;
    const Vec3 toLight = light.position - camera.position;
    const double d = length(toLight);
    // A camera inside the sphere sees it whole: a disc as wide as the methods take, right ahead.
    if (d <= light.radius) {
        sun.direction = normalize(camera.lookAt - camera.position);
        sun.angularRadiusDeg = 45;
        return sun;
    }
    sun.direction = toLight * (1.0 / d);
    sun.angularRadiusDeg = std::asin(light.radius / d) * 180.0 / std::numbers::pi;
    sun.distance = d - light.radius;
    return sun;
}

std::vector<SceneLight> sceneLights(const Scene& scene) {
    if (!scene.lights.empty()) return scene.lights;
    return {lightFromSun(scene.sun)};
}

std::vector<Triangle> groundTriangles(const Scene& scene) {
    if (!scene.ground) return {};
    const double r = scene.camera.farPlane, y = scene.ground->height;
    const double cx = scene.camera.position.x, cz = scene.camera.position.z;
    const Vec3 a{cx - r, y, cz - r}, b{cx + r, y, cz - r}, c{cx + r, y, cz + r},
        d{cx - r, y, cz + r};
    return {{a, b, c, scene.ground->color}, {a, c, d, scene.ground->color}};
}

Result<Scene> parseScene(const std::string& jsonText, const std::string& source) {
    auto doc = parseJsonText(
        jsonText, source,
        {64, kMaxSceneJsonValues, "a scene: 1,048,576 triangles, 65,536 lights and ~1M objects"});
    if (!doc) return doc.error();
    auto scene = readScene(*doc, JsonPlace(source));
    if (!scene) return scene.error();
    if (Status st = checkAcrossFields(*scene); !st)
        return invalidInput(source + ": " + st.error().message);
    scene->sun.direction = normalize(scene->sun.direction);
    return scene;
}

Result<Scene> loadScene(const std::string& path) {
    auto text = readTextFile(path, kMaxSceneFileBytes);
    if (!text) return text.error();
    return parseScene(*text, path);
}

}  // namespace flarekit
