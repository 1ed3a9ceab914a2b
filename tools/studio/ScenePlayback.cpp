// SPDX-License-Identifier: Apache-2.0
#include "ScenePlayback.h"

#include <cmath>

#include "core/Parallel.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/FramePipeline.h"
#include "flarekit/gl/HeadlessGl.h"
#include "flarekit/gl/SceneStill.h"
#include "scene/CameraMath.h"

namespace flarekit::studio {

Vec3 directionThrough(const Scene& scene, Point pixel) {
    // gluPerspective's frustum: the pixel's normalised device coordinates scaled by the half
    // field of view's tangent (times the aspect across), along the camera's basis.
    const CameraBasis b = cameraBasis(scene.camera);
    const double t = std::tan(scene.camera.fovYDeg * M_PI / 360.0);
    const double aspect = double(scene.width) / double(scene.height);
    const double nx = 2.0 * pixel.x / scene.width - 1.0, ny = 1.0 - 2.0 * pixel.y / scene.height;
    Vec3 d{b.forward.x + (b.right.x * nx * aspect + b.up.x * ny) * t,
           b.forward.y + (b.right.y * nx * aspect + b.up.y * ny) * t,
           b.forward.z + (b.right.z * nx * aspect + b.up.z * ny) * t};
    const double n = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return {d.x / n, d.y / n, d.z / n};
}

Result<std::unique_ptr<ScenePlayback>> ScenePlayback::open(const std::string& path,
                                                           const std::string& method,
                                                           const Preset& preset) {
    if (Status s = checkVisibilityMethod(method); !s) return s.error();
    auto scene = loadScene(path);
    if (!scene) return scene.error();
    if (Status s = checkFlareWork(preset, scene->width, scene->height, 1, "preset"); !s)
        return s.error();
    return std::unique_ptr<ScenePlayback>(new ScenePlayback(path, method, *scene, preset));
}

ScenePlayback::ScenePlayback(std::string path, std::string method, const Scene& scene,
                             const Preset& preset)
    : m_path(std::move(path)),
      m_method(std::move(method)),
      m_scene(scene),
      m_preset(preset),
      m_wanted(scene.sun.direction),
      m_thread([this] { work(); }) {}

ScenePlayback::~ScenePlayback() {
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
}

void ScenePlayback::aimSunAt(Point pixel) {
    {
        std::lock_guard lock(m_mutex);
        m_wanted = directionThrough(m_scene, pixel);
        ++m_generation;
    }
    m_wake.notify_all();
}

bool ScenePlayback::upToDate() const {
    std::lock_guard lock(m_mutex);
    return !m_error.empty() || (m_latest && m_latest->generation == m_generation);
}

std::optional<SceneFrame> ScenePlayback::latest() const {
    std::lock_guard lock(m_mutex);
    return m_latest;
}

std::string ScenePlayback::error() const {
    std::lock_guard lock(m_mutex);
    return m_error;
}

void ScenePlayback::work() {
    const auto fail = [this](const std::string& message) {
        std::lock_guard lock(m_mutex);
        m_error = message;
    };
    runOnThisThread([&] {
        gl::SceneStillOptions options;
        options.scene = m_path, options.method = m_method;
        auto context = gl::createFrameContext(m_scene.width, m_scene.height,
                                              options.render.msaaSamples, m_path + ": image");
        if (!context) return fail(context.error().message);
        auto pipeline = FramePipeline::create(m_scene, m_preset, gl::sceneStillSettings(options));
        if (!pipeline) return fail(pipeline.error().message);
        unsigned done = 0;
        for (;;) {
            Scene view = m_scene;
            unsigned generation = 0;
            {
                std::unique_lock lock(m_mutex);
                m_wake.wait(lock, [&] { return m_stop || m_generation != done; });
                if (m_stop) return;
                view.sun.direction = m_wanted, generation = m_generation;
            }
            auto frame = pipeline->run(view, 0.0);
            if (!frame) return fail(frame.error().message);
            SceneFrame still{std::move(frame->image), frame->rawCoverage, frame->sunPixel,
                             view.sun.direction, generation};
            std::lock_guard lock(m_mutex);
            m_latest = std::move(still);
            done = generation;
        }
    });
}

}  // namespace flarekit::studio
