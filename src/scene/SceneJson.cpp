// Scene JSON (the docs/architecture.md contract) with full validation: every error names the file
// and the field, and says what was expected.
#include "core/JsonText.h"
#include "flarekit/Image.h"
#include "flarekit/Scene.h"

namespace flarekit {

using json = nlohmann::json;

namespace {

//! Largest accepted scene triangle count: 4 million keeps a scene's memory under ~0.5 GB.
constexpr std::size_t kMaxTriangles = std::size_t(4) << 20;

std::string got(const json& v) {
    return jsonExcerpt(v);
}

struct SceneReader {
    std::string source;

    Error fail(const std::string& field, const std::string& what) const {
        return invalidInput(source + ": " + field + ": " + what);
    }

    // Each reader returns an Error when the value is wrong, nothing when it was read.
    std::optional<Error> keys(const json& obj, const std::string& at,
                              std::initializer_list<const char*> allowed) const {
        if (!obj.is_object()) return fail(at, "expected an object, got " + got(obj));
        for (const auto& [key, value] : obj.items()) {
            bool known = false;
            std::string list;
            for (const char* a : allowed) {
                known = known || key == a;
                list += (list.empty() ? "" : ", ") + std::string(a);
            }
            if (!known) return fail(at + "." + key, "unknown key (expected one of: " + list + ")");
        }
        return std::nullopt;
    }

    std::optional<Error> number(const json& obj, const std::string& at, const char* key,
                                double& out, bool required, double lo, double hi, bool loOpen,
                                const char* what) const {
        const auto it = obj.find(key);
        if (it == obj.end())
            return required ? std::optional(
                                  fail(at + "." + key, std::string("missing; expected ") + what))
                            : std::nullopt;
        const bool ok = it->is_number() && std::isfinite(it->get<double>()) &&
                        (loOpen ? it->get<double>() > lo : it->get<double>() >= lo) &&
                        it->get<double>() <= hi;
        if (!ok) return fail(at + "." + key, std::string("expected ") + what + ", got " + got(*it));
        out = it->get<double>();
        return std::nullopt;
    }

    std::optional<Error> vec3(const json& v, const std::string& field, Vec3& out,
                              bool nonNegative = false) const {
        const char* what = nonNegative ? "expected an array of 3 non-negative numbers"
                                       : "expected an array of 3 numbers";
        if (!v.is_array() || v.size() != 3)
            return fail(field, std::string(what) + ", got " + got(v));
        double c[3];
        for (std::size_t i = 0; i < 3; ++i) {
            if (!v[i].is_number() || !std::isfinite(v[i].get<double>()) ||
                (nonNegative && v[i].get<double>() < 0)) {
                return fail(field, std::string(what) + ", got " + got(v));
            }
            c[i] = v[i].get<double>();
        }
        out = {c[0], c[1], c[2]};
        return std::nullopt;
    }

    std::optional<Error> vec3(const json& obj, const std::string& at, const char* key, Vec3& out,
                              bool required, bool nonNegative = false) const {
        const auto it = obj.find(key);
        if (it == obj.end())
            return required ? std::optional(
                                  fail(at + "." + key, "missing; expected an array of 3 numbers"))
                            : std::nullopt;
        return vec3(*it, at + "." + key, out, nonNegative);
    }
};

#define FK_TRY(expr) \
    if (auto fk_err = (expr)) return *fk_err

Result<Scene> readScene(const json& doc, const SceneReader& r) {
    Scene s;
    FK_TRY(r.keys(doc, "(top level)", {"image", "camera", "sun", "objects"}));
    for (const char* section : {"image", "camera", "sun"}) {
        if (!doc.contains(section)) return r.fail(section, "missing; expected an object");
    }
    const json& image = doc["image"];
    FK_TRY(r.keys(image, "image", {"width", "height"}));
    double w = 0, h = 0;
    const std::string sizeWhat = "an integer in [1, " + std::to_string(kMaxImageSide) + "]";
    FK_TRY(r.number(image, "image", "width", w, true, 1, kMaxImageSide, false, sizeWhat.c_str()));
    FK_TRY(r.number(image, "image", "height", h, true, 1, kMaxImageSide, false, sizeWhat.c_str()));
    if (w != std::floor(w))
        return r.fail("image.width", "expected " + sizeWhat + ", got " + got(image["width"]));
    if (h != std::floor(h))
        return r.fail("image.height", "expected " + sizeWhat + ", got " + got(image["height"]));
    s.width = int(w);
    s.height = int(h);

    const json& cam = doc["camera"];
    FK_TRY(r.keys(cam, "camera", {"position", "look_at", "up", "fov_y_deg", "near", "far"}));
    FK_TRY(r.vec3(cam, "camera", "position", s.camera.position, true));
    FK_TRY(r.vec3(cam, "camera", "look_at", s.camera.lookAt, true));
    FK_TRY(r.vec3(cam, "camera", "up", s.camera.up, false));
    FK_TRY(r.number(cam, "camera", "fov_y_deg", s.camera.fovYDeg, false, 0, 179, true,
                    "a number in (0, 179]"));
    FK_TRY(r.number(cam, "camera", "near", s.camera.nearPlane, false, 0, 1e12, true,
                    "a positive number"));
    FK_TRY(r.number(cam, "camera", "far", s.camera.farPlane, false, 0, 1e12, true,
                    "a positive number"));
    if (s.camera.farPlane <= s.camera.nearPlane)
        return r.fail("camera.far", "expected a number greater than camera.near");
    const Vec3 view = s.camera.lookAt - s.camera.position;
    if (length(view) < 1e-12)
        return r.fail("camera.look_at", "expected a point different from camera.position");
    if (length(cross(normalize(view), s.camera.up)) < 1e-9) {
        return r.fail("camera.up", "expected a direction not parallel to the view direction");
    }

    const json& sun = doc["sun"];
    FK_TRY(r.keys(sun, "sun", {"direction", "angular_radius_deg", "color", "intensity"}));
    FK_TRY(r.vec3(sun, "sun", "direction", s.sun.direction, true));
    if (length(s.sun.direction) < 1e-12)
        return r.fail("sun.direction", "expected a non-zero direction");
    s.sun.direction = normalize(s.sun.direction);
    FK_TRY(r.number(sun, "sun", "angular_radius_deg", s.sun.angularRadiusDeg, false, 0, 45, true,
                    "a number in (0, 45]"));
    FK_TRY(r.vec3(sun, "sun", "color", s.sun.color, false, true));
    FK_TRY(r.number(sun, "sun", "intensity", s.sun.intensity, false, 0, 1e9, false,
                    "a non-negative number"));

    const auto objects = doc.find("objects");
    if (objects == doc.end()) return s;
    if (!objects->is_array()) return r.fail("objects", "expected an array, got " + got(*objects));
    for (std::size_t i = 0; i < objects->size(); ++i) {
        const json& o = (*objects)[i];
        const std::string at = "objects[" + std::to_string(i) + "]";
        if (!o.is_object()) return r.fail(at, "expected an object, got " + got(o));
        const auto type = o.find("type");
        const std::string t = type != o.end() && type->is_string() ? type->get<std::string>() : "";
        Vec3 color{0.5, 0.5, 0.5};
        if (t == "sphere") {
            FK_TRY(r.keys(o, at, {"type", "center", "radius", "color"}));
            Sphere sp;
            FK_TRY(r.vec3(o, at, "center", sp.center, true));
            FK_TRY(r.number(o, at, "radius", sp.radius, true, 0, 1e12, true, "a positive number"));
            FK_TRY(r.vec3(o, at, "color", sp.color, false, true));
            s.spheres.push_back(sp);
        } else if (t == "box") {
            FK_TRY(r.keys(o, at, {"type", "min", "max", "color"}));
            Box b;
            FK_TRY(r.vec3(o, at, "min", b.min, true));
            FK_TRY(r.vec3(o, at, "max", b.max, true));
            if (!(b.min.x < b.max.x && b.min.y < b.max.y && b.min.z < b.max.z)) {
                return r.fail(at + ".max", "expected every component greater than min's");
            }
            FK_TRY(r.vec3(o, at, "color", b.color, false, true));
            s.boxes.push_back(b);
        } else if (t == "triangles") {
            FK_TRY(r.keys(o, at, {"type", "vertices", "color"}));
            FK_TRY(r.vec3(o, at, "color", color, false, true));
            const auto v = o.find("vertices");
            if (v == o.end() || !v->is_array() || v->empty() || v->size() % 3 != 0) {
                return r.fail(at + ".vertices",
                              "expected an array of 3N vertices (N >= 1), got " +
                                  (v == o.end() ? std::string("nothing") : got(*v)));
            }
            if (s.triangles.size() + v->size() / 3 > kMaxTriangles) {
                return r.fail(
                    at + ".vertices",
                    "expected at most " + std::to_string(kMaxTriangles) + " triangles in a scene");
            }
            for (std::size_t k = 0; k < v->size(); k += 3) {
                Triangle tri;
                tri.color = color;
                FK_TRY(r.vec3((*v)[k], at + ".vertices[" + std::to_string(k) + "]", tri.a));
                FK_TRY(r.vec3((*v)[k + 1], at + ".vertices[" + std::to_string(k + 1) + "]", tri.b));
                FK_TRY(r.vec3((*v)[k + 2], at + ".vertices[" + std::to_string(k + 2) + "]", tri.c));
                s.triangles.push_back(tri);
            }
        } else {
            return r.fail(at + ".type",
                          "expected \"sphere\", \"box\" or \"triangles\", got " +
                              (type == o.end() ? std::string("nothing") : got(*type)));
        }
    }
    return s;
}

#undef FK_TRY

}  // namespace

Result<Scene> parseScene(const std::string& jsonText, const std::string& source) {
    auto doc = parseJsonText(jsonText, source);
    if (!doc) return doc.error();
    return readScene(*doc, SceneReader{source});
}

Result<Scene> loadScene(const std::string& path) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    return parseScene(*text, path);
}

}  // namespace flarekit
