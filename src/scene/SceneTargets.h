// SPDX-License-Identifier: Apache-2.0
// A SceneRenderer's GL objects, for the GPU passes that read its frame (the occlusion methods,
// the sprite flare, the tone map). Internal: the public SceneRenderer hands out no GL names.
#pragma once

#include <epoxy/gl.h>

#include "flarekit/gl/Render.h"

namespace flarekit {

struct SceneTargets {
    GLuint color = 0;        //!< RGBA16F, single-sample (resolved)
    GLuint depth = 0;        //!< DEPTH_COMPONENT32F, single-sample (resolved)
    GLuint framebuffer = 0;  //!< holds color + depth
    GLuint multisampleDepth =
        0;  //!< with MSAA, the depth before its resolve (GL_TEXTURE_2D_MULTISAMPLE); else 0
    GLuint meshVertexArray =
        0;  //!< the uploaded objects (positions, normals, colours at attributes 0-2)
    int msaaSamples = 1;
    //! R16F, single-sample: the share of light let through by the translucent objects in front
    //! of each pixel's opaque depth (0 when the scene has none).
    GLuint transmittance = 0;
};

SceneTargets sceneTargets(const SceneRenderer& renderer);

}  // namespace flarekit
