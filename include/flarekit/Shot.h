// SPDX-License-Identifier: Apache-2.0
// Shots: numbered image sequences (shot.####.exr, shot.%04d.exr), frame ranges as a render
// farm hands them out (A-B:step), a light's position keyed per frame (a track file), and how
// much of the light's disc a foreground hides (a matte or a depth pass). What a compositor's
// flare tools (Nuke's Flare node, Optical Flares, Knoll Light Factory) take as their input.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/Scene.h"

namespace flarekit {

//! A sequence's file name: everything around one frame-number token. "####" pads to as many
//! digits as there are '#' (Nuke, Houdini, Deadline); "%04d" (printf, ffmpeg, OpenCue) pads to
//! its width; "%d" does not pad. Frame numbers are whole numbers from 0.
struct FramePattern {
    std::string prefix, suffix;
    int padding = 0;
    //! The file of `frame`: "shot." + "1001" + ".exr".
    std::string path(int frame) const;
};

//! Whether `text` holds a frame token ("#" run, "%d", "%0Nd"): a sequence, not a single file.
bool isFramePattern(const std::string& text);
//! The pattern `text` names; an error when it has no frame token or more than one.
Result<FramePattern> parseFramePattern(const std::string& text);
//! The frames whose files exist, ascending: the directory listed once, names matched against
//! the pattern (a number of exactly `padding` digits, or more without a leading zero).
std::vector<int> framesOnDisk(const FramePattern& pattern);

//! --frames: "A-B" or "A-B:step" or "N" (a farm chunk), every frame from A to B that is A plus
//! a multiple of step.
struct FrameRange {
    int first = 0, last = 0, step = 1;
    std::vector<int> frames() const;
};
//! The most frames one range may hold (parseFrameRange refuses more).
inline constexpr long long kMaxFramesPerRun = 1000000;
//! `option` names the flag in messages ("--frames: expected A-B[:step] ...").
Result<FrameRange> parseFrameRange(const std::string& text, const std::string& option);
//! Gaps as ranges: {5, 6, 7, 10} -> "5-7, 10".
std::string describeFrames(const std::vector<int>& frames);

//! A light's position per frame: pixels from the top-left, pixel centres at +0.5 (the same
//! convention as --light X,Y), with an optional intensity multiplier per key.
struct LightKey {
    double frame = 0;
    double x = 0, y = 0;
    double intensity = 1;
};
struct LightTrack {
    std::vector<LightKey> keys;  //!< strictly ascending frames, finite values
    bool hasIntensity = false;
    struct Sample {
        Point position;
        float intensity = 1;
        bool held = false;  //!< before the first key or after the last: the end key held
    };
    //! Linear between the two keys around `frame`; the nearest end key outside them.
    Sample at(double frame) const;
};
//! A track from CSV (header line "frame,x,y" or "frame,x,y,intensity") or JSON (an array, or
//! {"keys": [...]}, of {"frame", "x", "y"[, "intensity"]}), told apart by the first character.
//! Errors name the file, the line or key and the field: unsorted frames, non-finite values,
//! negative intensities, a bad header.
Result<LightTrack> parseLightTrack(const std::string& text, const std::string& source);
Result<LightTrack> loadLightTrack(const std::string& path);
//! The track as CSV, in the format parseLightTrack reads (--write-track).
std::string lightTrackCsv(const LightTrack& track);

//! A camera per frame (--camera): keys in the Scene JSON camera form, each with its "frame";
//! position, look_at, up and fov_y_deg linear between keys, the end keys held outside them.
struct CameraKey {
    double frame = 0;
    SceneCamera camera;
};
struct CameraTrack {
    std::vector<CameraKey> keys;  //!< strictly ascending frames
    SceneCamera at(double frame, bool* held = nullptr) const;
};
//! {"frames": [{"frame": 1001, "position": [...], "look_at": [...], ...}, ...]} or the array
//! alone; every key checked as a scene's camera is ("cam.json: frames[2].fov_y_deg: ...").
Result<CameraTrack> parseCameraTrack(const std::string& text, const std::string& source);
Result<CameraTrack> loadCameraTrack(const std::string& path);
//! Where a light projects in a width x height frame seen by `camera`: a point in the world
//! (`isDirection` false) or a direction toward a distant light such as the sun (true). False
//! when it is behind the camera.
bool projectLight(const SceneCamera& camera, int width, int height, Vec3 light, bool isDirection,
                  Point& pixel);

//! --light auto over a sequence: one light followed from frame to frame. It follows the accepted
//! light nearest where it is predicted, inside a gate (an alpha-beta filter on the
//! luminance-weighted centroids: smooth, no lag at constant speed), and changes to
//! another only when that one has carried more than `switchRatio` times the followed one's flux for
//! `switchFrames` frames in a row, so a one-frame sparkle elsewhere, however bright, does not move
//! it and two equal highlights do not trade it back and forth.
struct TrackerParams {
    //! Position gain: half the distance to each measurement, a quarter of a pixel of jitter
    //! passed on per pixel of centroid noise.
    double alpha = 0.5;
    //! Velocity gain (the critically damped pair of alpha 0.5, beta = alpha^2 / (2 - alpha)).
    double beta = 0.5 * 0.5 / 1.5;
    double switchRatio = 2.0;
    int switchFrames = 3;  //!< 0.125 s at 24 fps: longer than a glint, short for a real change
    //! A measurement farther than this from the prediction is another light, in units of the
    //! followed light's radius plus 4 px, and never less than minGatePixels.
    double gate = 3.0;
    //! 64 px: a fast pan moves a light 20-50 px a frame at 1080p, and the first frames predict
    //! no motion at all.
    double minGatePixels = 64.0;
};
struct TrackedLight {
    bool found = false;  //!< false before any light, or while the followed one is not seen
    Point position;
    double flux = 0;
    float flareScale = 0;
};
class LightTracker {
  public:
    explicit LightTracker(const TrackerParams& params = {}) : m_params(params) {}
    //! One frame: the light finder's candidates in it (LightSearch::candidates; only accepted
    //! ones start or take over the track), `dt` frames since the previous update.
    TrackedLight update(const std::vector<LightCandidate>& lights, double dt);

  private:
    TrackerParams m_params;
    bool m_started = false;
    Point m_position, m_velocity;
    float m_radius = 0;
    int m_challenged = 0;  //!< frames in a row a brighter light stood elsewhere
    int m_measured = 0;    //!< sightings of the followed light so far
    float m_peak = 0;      //!< the followed light's peak when last seen
    Point m_challenger;
};

//! What hides the light in a frame.
struct Occluder {
    int channel = 3;  //!< the channel of the image holding the matte or the depth
    //! Matte (nullopt): a pixel hides the light by its value (1 = opaque foreground). Depth: a
    //! pixel hides it when it is nearer than this distance (same units as the depth pass).
    std::optional<float> lightDepth;
};
//! The light's visibility in one frame: the mean, over its disc of `radius` px around
//! `centre`, of each pixel's visibility (1 - matte, or depth >= lightDepth), each pixel weighed
//! by the share of its area inside the disc (pixels the rim crosses are sampled 16 x 16). Only
//! the part of the disc inside the frame counts; a disc wholly outside it is visible (1).
//! A radius under half a pixel is the one pixel under the centre.
double discVisibility(const Image& image, const Occluder& occluder, Point centre, double radius);

}  // namespace flarekit
