// The Scene JSON contract of architecture.md: a gluLookAt camera, a sun at infinity with an
// angular radius, and opaque spheres, boxes and triangles.
#pragma once

#include <string>
#include <vector>

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

struct SceneSun {
    Vec3 direction{0.2, 0.3, -1};  //!< from the camera toward the sun; normalised on load
    double angularRadiusDeg = 1.5;
    Vec3 color{1.0, 0.95, 0.85};
    double intensity = 50.0;
};

struct Sphere {
    Vec3 center;
    double radius = 1;
    Vec3 color{0.5, 0.5, 0.5};
};

struct Box {
    Vec3 min, max;
    Vec3 color{0.5, 0.5, 0.5};
};

struct Triangle {
    Vec3 a, b, c;  //!< double-sided
    Vec3 color{0.5, 0.5, 0.5};
};

struct Scene {
    int width = 640, height = 360;
    SceneCamera camera;
    SceneSun sun;
    std::vector<Sphere> spheres;
    std::vector<Box> boxes;
    std::vector<Triangle> triangles;
};

//! Parses and validates; errors name the field: "scene.json: objects[4].radius: expected a
//! positive number, got -1".
Result<Scene> parseScene(const std::string& jsonText, const std::string& source);
Result<Scene> loadScene(const std::string& path);

}  // namespace flarekit
