// SPDX-License-Identifier: Apache-2.0
// The Scene JSON contract of docs/architecture.md: a gluLookAt camera, lights (a sun at infinity
// with an angular radius, directional lights like it and sphere-shaped point lights) and
// spheres, boxes and triangles, opaque or partly transmitting (glass, foliage, fog cards).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Param.h"
#include "flarekit/Result.h"
#include "flarekit/Vec3.h"

namespace flarekit {

struct SceneCamera {
    Vec3 position{0, 1.7, 0};
    Vec3 lookAt{0, 5, -20};
    Vec3 up{0, 1, 0};
    double fovYDeg = 60;  //!< vertical field of view, degrees
    double nearPlane = 0.1, farPlane = 2000;
};
inline constexpr double kSceneAnyCoordinate = -kParamUnbounded;
//! The MSAA sample counts a scene may be rendered with: those every GL 4.5 implementation
//! supports for RGBA8/depth targets (the GL renderer's and the demo's "msaa" choices).
inline constexpr int kMsaaSampleCounts[] = {1, 2, 4, 8};
inline constexpr Param<SceneCamera> kSceneCameraParams[] = {
    required(param<&SceneCamera::position>("position", kSceneAnyCoordinate, kParamUnbounded, "m",
                                           "eye point")),
    required(param<&SceneCamera::lookAt>("look_at", kSceneAnyCoordinate, kParamUnbounded, "m",
                                         "the point looked at")),
    param<&SceneCamera::up>("up", kSceneAnyCoordinate, kParamUnbounded, "",
                            "up direction (not parallel to the view)"),
    aboveMin(
        param<&SceneCamera::fovYDeg>("fov_y_deg", 0, 179, "degrees", "vertical field of view")),
    aboveMin(
        param<&SceneCamera::nearPlane>("near", 0, kParamUnbounded, "m", "near clipping distance")),
    aboveMin(param<&SceneCamera::farPlane>("far", 0, kParamUnbounded, "m",
                                           "far clipping distance (> near)")),
};

struct SceneSun {
    Vec3 direction{0.2, 0.3, -1};  //!< from the camera toward the sun; normalised on load
    double angularRadiusDeg = 1.5;
    Vec3 color{1.0, 0.95, 0.85};
    double intensity = 2400.0;  //!< radiance of the disc: a low sun is 10^3-10^5 x its sky
    //! 0: at infinity. Set (in code, not in the Scene JSON) when a sphere light stands in as
    //! the sun of the one-light GPU methods (lightAsSun): the distance to its near side, so
    //! only what lies before it hides it.
    double distance = 0;
};
inline constexpr Param<SceneSun> kSceneSunParams[] = {
    required(param<&SceneSun::direction>("direction", kSceneAnyCoordinate, kParamUnbounded, "",
                                         "from the camera toward the sun (non-zero; normalised)")),
    aboveMin(
        param<&SceneSun::angularRadiusDeg>("angular_radius_deg", 0, 45, "degrees", "disc radius")),
    param<&SceneSun::color>("color", 0, kParamUnbounded, "linear RGB", "sun colour"),
    param<&SceneSun::intensity>("intensity", 0, kParamUnbounded, "linear",
                                "radiance of the disc (colour x intensity); lights surfaces by "
                                "its solid angle and sets the flare by its flux"),
};

//! Opacity of an object: a ray through it keeps 1 - opacity of its light (once per object,
//! however many of its surfaces it crosses; each triangle of a "triangles" object counts apart).
inline constexpr double kOpaque = 1.0;

struct Sphere {
    Vec3 center;
    double radius = 1;
    Vec3 color{0.5, 0.5, 0.5};
    double opacity = kOpaque;
};
inline constexpr Param<Sphere> kSphereParams[] = {
    required(param<&Sphere::center>("center", kSceneAnyCoordinate, kParamUnbounded, "m", "centre")),
    required(aboveMin(param<&Sphere::radius>("radius", 0, kParamUnbounded, "m", "radius"))),
    param<&Sphere::color>("color", 0, kParamUnbounded, "linear RGB", "albedo"),
    param<&Sphere::opacity>("opacity", 0, 1, "",
                            "share of light a ray through it loses (1 opaque, 0 invisible)"),
};

struct Box {
    Vec3 min, max;
    Vec3 color{0.5, 0.5, 0.5};
    double opacity = kOpaque;
};
inline constexpr Param<Box> kBoxParams[] = {
    required(param<&Box::min>("min", kSceneAnyCoordinate, kParamUnbounded, "m", "lowest corner")),
    required(param<&Box::max>("max", kSceneAnyCoordinate, kParamUnbounded, "m",
                              "highest corner (each component > min's)")),
    param<&Box::color>("color", 0, kParamUnbounded, "linear RGB", "albedo"),
    param<&Box::opacity>("opacity", 0, 1, "",
                         "share of light a ray through it loses (1 opaque, 0 invisible)"),
};

struct Triangle {
    Vec3 a, b, c;  //!< double-sided
    Vec3 color{0.5, 0.5, 0.5};
    double opacity = kOpaque;
};

//! Triangles' shared colour and opacity ("vertices" is read apart: an array of 3N points).
struct TrianglesColor {
    Vec3 color{0.5, 0.5, 0.5};
    double opacity = kOpaque;
};
inline constexpr Param<TrianglesColor> kTrianglesParams[] = {
    param<&TrianglesColor::color>("color", 0, kParamUnbounded, "linear RGB",
                                  "albedo of every triangle"),
    param<&TrianglesColor::opacity>("opacity", 0, 1, "",
                                    "share of light a ray through a triangle loses"),
};

//! An optional ground plane y = height, as far as the camera sees (a square of half side
//! camera.far around it): it occludes like any object, so a sun below the horizon is hidden.
struct Ground {
    double height = 0;
    Vec3 color{0.25, 0.3, 0.2};
};
inline constexpr Param<Ground> kGroundParams[] = {
    param<&Ground::height>("height", kSceneAnyCoordinate, kParamUnbounded, "m",
                           "the plane y = height"),
    param<&Ground::color>("color", 0, kParamUnbounded, "linear RGB", "albedo"),
};

enum class LightType { Directional = 0, Point = 1 };

//! One light of the "lights" array. Directional: at infinity toward `direction`, a disc of
//! `angularRadiusDeg` (the sun's model). Point: a sphere of `radius` at `position`.
struct SceneLight {
    LightType type = LightType::Directional;
    Vec3 direction{0.2, 0.3, -1};  //!< directional: from the camera toward it; normalised on load
    double angularRadiusDeg = 0.27;
    Vec3 position{0, 0, 0};  //!< point: centre
    double radius = 0.1;     //!< point: sphere radius
    Vec3 color{1, 1, 1};
    double intensity = 50;                   //!< radiance of the disc or sphere, like the sun's
    std::string preset = "tanczos-classic";  //!< the sprite flare it draws ("" draws none)
};
inline constexpr Param<SceneLight> kDirectionalLightParams[] = {
    required(param<&SceneLight::direction>("direction", kSceneAnyCoordinate, kParamUnbounded, "",
                                           "from the camera toward the light (non-zero)")),
    aboveMin(param<&SceneLight::angularRadiusDeg>("angular_radius_deg", 0, 45, "degrees",
                                                  "disc radius")),
    param<&SceneLight::color>("color", 0, kParamUnbounded, "linear RGB", "light colour"),
    param<&SceneLight::intensity>("intensity", 0, kParamUnbounded, "linear",
                                  "radiance of the disc (colour x intensity)"),
};
inline constexpr Param<SceneLight> kPointLightParams[] = {
    required(param<&SceneLight::position>("position", kSceneAnyCoordinate, kParamUnbounded, "m",
                                          "centre of the sphere light")),
    aboveMin(param<&SceneLight::radius>("radius", 0, kParamUnbounded, "m", "sphere radius")),
    param<&SceneLight::color>("color", 0, kParamUnbounded, "linear RGB", "light colour"),
    param<&SceneLight::intensity>("intensity", 0, kParamUnbounded, "linear",
                                  "radiance of the sphere (colour x intensity)"),
};

SceneLight lightFromSun(const SceneSun& sun);
//! A light as the sun the one-light GPU methods measure, seen from `camera`: a directional
//! light as it is; a point light as the disc its sphere subtends (direction to its centre,
//! angular radius asin(radius / distance)) at the distance of its near side.
SceneSun lightAsSun(const SceneLight& light, const SceneCamera& camera);

struct Scene {
    int width = 640, height = 360;
    SceneCamera camera;
    //! The first directional light, for the one-sun paths (renderer sky, GPU methods, flare).
    //! With no directional light among `lights` its intensity is 0.
    SceneSun sun;
    //! Every light in scene order. Empty means the sun is the only light (scenes built in
    //! code, Scene JSON without "lights"); see sceneLights().
    std::vector<SceneLight> lights;
    std::vector<Sphere> spheres;
    std::vector<Box> boxes;
    std::vector<Triangle> triangles;
    std::optional<Ground> ground;
};

//! The scene's lights in order: `lights`, or the sun alone when that is empty.
std::vector<SceneLight> sceneLights(const Scene& scene);
//! Largest number of lights in a scene: 65,536 keeps the ground truth of all of them within
//! minutes and is past any engine's on-screen flare count.
inline constexpr std::size_t kMaxSceneLights = 65536;

//! The ground as the two triangles every renderer and the ray caster draw (none without one).
std::vector<Triangle> groundTriangles(const Scene& scene);
//! The "image" section of the Scene JSON.
inline constexpr Param<Scene> kSceneImageParams[] = {
    required(param<&Scene::width>("width", 1, kMaxImageSide, "pixels", "frame width")),
    required(param<&Scene::height>("height", 1, kMaxImageSide, "pixels", "frame height")),
};

//! Every field against the tables above, plus what no single field can say (the camera looks
//! somewhere, up is not the view direction, far > near, the sun has a direction, each box's
//! max > min, at most 4 Mi triangles): the check of parsed scenes and of scenes built in code
//! (raycastVisibility, SceneRenderer::create, FramePipeline::create). "camera.far: expected ...".
Status validateScene(const Scene& scene);

//! Parses and validates; errors name the field: "scene.json: objects[4].radius: expected a
//! positive number, got -1".
Result<Scene> parseScene(const std::string& jsonText, const std::string& source);
Result<Scene> loadScene(const std::string& path);

}  // namespace flarekit
