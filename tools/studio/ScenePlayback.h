// SPDX-License-Identifier: Apache-2.0
// A Scene JSON in the studio: its still rendered as `flarekit render` renders it (the same
// pipeline settings, sceneStillSettings), by a worker with a headless GL context of its own,
// again whenever the sun is moved. The pointer aims the sun: the direction that projects to the
// pointer's pixel through the scene's camera.
#pragma once

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/Scene.h"

namespace flarekit::studio {

struct SceneFrame {
    Image hdr;  //!< linear HDR, as `render` writes it to a float file
    double coverage = 0;
    Point sun;
    Vec3 direction;
    unsigned generation = 0;
};

//! The unit direction from the camera that projects to `pixel` (top-left origin, pixel
//! centres at +0.5), the inverse of projectLight for a direction.
Vec3 directionThrough(const Scene& scene, Point pixel);

class ScenePlayback {
  public:
    //! Loads and checks the scene and the method, then starts the worker on its still.
    static Result<std::unique_ptr<ScenePlayback>> open(const std::string& path,
                                                       const std::string& method,
                                                       const Preset& preset);
    ~ScenePlayback();
    ScenePlayback(const ScenePlayback&) = delete;
    ScenePlayback& operator=(const ScenePlayback&) = delete;

    const Scene& scene() const { return m_scene; }
    const std::string& path() const { return m_path; }
    const std::string& method() const { return m_method; }
    //! Aims the sun through `pixel`; the worker renders that next (a newer aim replaces it).
    void aimSunAt(Point pixel);
    //! The still of the newest aim has been made (or the worker stopped on an error).
    bool upToDate() const;
    std::optional<SceneFrame> latest() const;
    std::string error() const;

  private:
    ScenePlayback(std::string path, std::string method, const Scene& scene, const Preset& preset);
    void work();

    std::string m_path, m_method;
    Scene m_scene;
    Preset m_preset;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    Vec3 m_wanted;                       //!< guarded by m_mutex
    unsigned m_generation = 1;           //!< of m_wanted, guarded
    std::optional<SceneFrame> m_latest;  //!< guarded
    std::string m_error;                 //!< guarded
    bool m_stop = false;                 //!< guarded
    std::thread m_thread;                //!< last: starts after every member it reads exists
};

}  // namespace flarekit::studio
