// SPDX-License-Identifier: Apache-2.0
// A camera keyed per frame, read through the scene camera's own parameter table, and the light
// projected through it.
#include <cstdio>

#include "core/ParamJson.h"
#include "flarekit/ParamText.h"
#include "flarekit/Shot.h"
#include "scene/CameraMath.h"

namespace flarekit {

namespace {
Vec3 mix(Vec3 a, Vec3 b, double t) {
    return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
}
}  // namespace

SceneCamera CameraTrack::at(double frame, bool* held) const {
    if (held) *held = frame < keys.front().frame || frame > keys.back().frame;
    if (frame <= keys.front().frame) return keys.front().camera;
    if (frame >= keys.back().frame) return keys.back().camera;
    std::size_t i = 1;
    while (keys[i].frame < frame) ++i;
    const SceneCamera &a = keys[i - 1].camera, &b = keys[i].camera;
    const double t = (frame - keys[i - 1].frame) / (keys[i].frame - keys[i - 1].frame);
    SceneCamera c = a;
    c.position = mix(a.position, b.position, t);
    c.lookAt = mix(a.lookAt, b.lookAt, t);
    c.up = mix(a.up, b.up, t);
    c.fovYDeg = a.fovYDeg + (b.fovYDeg - a.fovYDeg) * t;
    return c;
}

Result<CameraTrack> parseCameraTrack(const std::string& text, const std::string& source) {
    JsonLimits limits;
    limits.what = "a camera track";
    auto json = parseJsonText(text, source, limits);
    if (!json) return json.error();
    const JsonPlace top(source);
    const nlohmann::json* frames = &*json;
    JsonPlace at = top;
    if (json->is_object()) {
        if (!json->contains("frames") || json->size() != 1)
            return top.fail("expected {\"frames\": [...]} or an array of cameras");
        frames = &(*json)["frames"];
        at = top / "frames";
    }
    if (!frames->is_array() || frames->empty())
        return at.fail("expected a non-empty array of cameras, each with its \"frame\"");
    CameraTrack track;
    for (std::size_t i = 0; i < frames->size(); ++i) {
        const nlohmann::json& k = (*frames)[i];
        const JsonPlace place = at.index(i);
        CameraKey key;
        if (auto e = readParams<SceneCamera>(k, kSceneCameraParams, key.camera, place, {"frame"}))
            return *e;
        const auto f = k.find("frame");
        if (f == k.end() || !f->is_number() || !std::isfinite(f->get<double>()))
            return (place / "frame").fail("expected the frame number");
        key.frame = f->get<double>();
        if (Status s = validateParams<SceneCamera>(key.camera, kSceneCameraParams,
                                                   source + ": " + place.at() + ".");
            !s)
            return s.error();
        const Vec3 view = key.camera.lookAt - key.camera.position;
        if (length(view) <= 0)
            return (place / "look_at").fail("expected a point different from position");
        if (length(cross(normalize(view), key.camera.up)) < 1e-9)
            return (place / "up").fail("expected a direction not parallel to the view direction");
        if (!track.keys.empty() && !(key.frame > track.keys.back().frame)) {
            char what[120];
            std::snprintf(what, sizeof what, "frame %g does not come after frame %g", key.frame,
                          track.keys.back().frame);
            return (place / "frame").fail(what);
        }
        track.keys.push_back(key);
    }
    return track;
}

Result<CameraTrack> loadCameraTrack(const std::string& path) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    return parseCameraTrack(*text, path);
}

bool projectLight(const SceneCamera& camera, int width, int height, Vec3 light, bool isDirection,
                  Point& pixel) {
    Scene scene;
    scene.camera = camera;
    scene.width = width;
    scene.height = height;
    return isDirection ? projectDirection(scene, light, pixel) : projectPoint(scene, light, pixel);
}

}  // namespace flarekit
