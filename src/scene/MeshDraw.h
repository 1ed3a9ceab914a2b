// SPDX-License-Identifier: Apache-2.0
// What every GL pass that draws a scene's objects shares: uploading a mesh, and drawing its
// translucent objects one by one (the scene renderer's colour and transmittance passes, the
// texture-mask occluders).
#pragma once

#include <epoxy/gl.h>

#include <vector>

#include "gl/GlObjects.h"
#include "scene/SceneMesh.h"

namespace flarekit {

//! Uploads `mesh` into a new buffer in `vertices` and points `vao`'s attributes 0-2
//! (position, normal, colour) at it; `count` receives its vertex count.
Status uploadMesh(const std::vector<MeshVertex>& mesh, GLuint vao, gl::Buffer& vertices,
                  GLsizei& count);

//! Draws each range of the bound vertex array with the bound program, after
//! `setOpacity(range.opacity)`; closed objects by their front faces. Culling is off after.
template <class SetOpacity>
void drawTranslucent(const std::vector<TranslucentRange>& ranges, SetOpacity setOpacity) {
    for (const TranslucentRange& r : ranges) {
        setOpacity(r.opacity);
        if (r.closed) {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
        } else {
            glDisable(GL_CULL_FACE);
        }
        glDrawArrays(GL_TRIANGLES, r.first, r.count);
    }
    glDisable(GL_CULL_FACE);
}

}  // namespace flarekit
