// SPDX-License-Identifier: Apache-2.0
// Rendering a scene with OpenGL (headless) and putting the sprite flare on it with the sun's
// measured coverage. A GL context must be current (gl::HeadlessGl) for renderScene.
#pragma once

#include <memory>

#include "flarekit/Flare.h"
#include "flarekit/Image.h"
#include "flarekit/Scene.h"
#include "flarekit/SunFlare.h"
#include "flarekit/Visibility.h"

namespace flarekit {

struct RenderOptions {
    //! Samples per pixel: 1 (no MSAA) or 2, 4, 8. Multisampled frames are resolved into the
    //! single-sample colour and depth textures after each draw.
    int msaaSamples = 1;
    //! Sun shadows from a shadow map (2048^2, orthographic from the sun) covering
    //! `shadowRange` metres around the view ahead of the camera; outside it, surfaces are lit.
    bool shadows = true;
    double shadowRange = 160;
};
inline constexpr Param<RenderOptions> kRenderParams[] = {
    oneOf<&RenderOptions::msaaSamples>("msaa", kMsaaSampleCounts, "samples",
                                       "samples per pixel of the scene pass"),
};

struct SceneTargets;

//! A GL scene renderer that keeps its programs, targets and the scene's mesh between frames,
//! so an animation pays only for drawing. A GL context must be current while it lives; it
//! is move-only.
class SceneRenderer {
  public:
    //! Targets of the scene's image size; uploads the scene's objects once.
    static Result<SceneRenderer> create(const Scene& scene, const RenderOptions& options = {});
    ~SceneRenderer();
    SceneRenderer(SceneRenderer&&) noexcept;
    SceneRenderer& operator=(SceneRenderer&&) noexcept;

    //! Replaces the uploaded objects with the scene's (same image size).
    Status setGeometry(const Scene& scene);
    //! Draws sky, sun and the uploaded objects seen by `scene`'s camera and sun (its objects
    //! are not re-read). Stays on the GPU: nothing is read back.
    Status draw(const Scene& scene);
    //! The last frame as linear HDR RGBA, top row first (waits for the GPU).
    Result<Image> readColor() const;

    int width() const;
    int height() const;
    //! Samples per pixel of the scene pass.
    int msaaSamples() const;

  private:
    struct Impl;
    explicit SceneRenderer(std::unique_ptr<Impl> impl);
    friend SceneTargets sceneTargets(
        const SceneRenderer& renderer);  // the GL passes' view (src/scene)
    std::unique_ptr<Impl> m;
};

//! One frame with a throwaway SceneRenderer: linear HDR RGBA with the sky gradient, the sun
//! disc at infinity (colour x intensity) and lit objects, from RGBA16F + 32-bit float depth.
Result<Image> renderScene(const Scene& scene, const RenderOptions& options = {});

}  // namespace flarekit
