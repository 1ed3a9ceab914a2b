// SPDX-License-Identifier: Apache-2.0
// flarekit's own scenes as texture-mask occluders: two meshes (opaque, translucent) and one
// small program, drawn from each light's sun-map camera by the engine's callback.
#include <epoxy/gl.h>

#include "flarekit/gl/EngineScene.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"
#include "scene/MeshDraw.h"
#include "scene/SceneMesh.h"

namespace flarekit {

namespace {
//! A mesh drawn from each sun-map camera: its vertex array, buffer and vertex count.
struct Mesh {
    gl::VertexArray vao = gl::makeVertexArray();
    gl::Buffer vertices;
    GLsizei count = 0;
};
}  // namespace

struct SceneOccluders::Impl {
    gl::Program program;
    GLint viewProjection = -1, keep = -1;
    Mesh opaque, translucent;
    std::vector<TranslucentRange> ranges;
};

SceneOccluders::SceneOccluders(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
SceneOccluders::~SceneOccluders() = default;

Result<std::unique_ptr<SceneOccluders>> SceneOccluders::create(const Scene& scene) {
    if (Status s = gl::requireCurrentContext("SceneOccluders::create"); !s) return s.error();
    auto program = gl::linkProgram({{GL_VERTEX_SHADER, "occluder.vert", shaders::occluder_vert},
                                    {GL_FRAGMENT_SHADER, "occluder.frag", shaders::occluder_frag}});
    if (!program) return program.error();
    auto m = std::make_unique<Impl>();
    m->program = std::move(*program);
    m->viewProjection = gl::uniformLocation(m->program.get(), "viewProjection");
    m->keep = gl::uniformLocation(m->program.get(), "keep");
    const Scene opaque = opaqueObjects(scene), clear = translucentObjects(scene);
    for (auto [mesh, objects] :
         {std::pair{&m->opaque, &opaque}, std::pair{&m->translucent, &clear}}) {
        if (Status s =
                uploadMesh(buildSceneMesh(*objects), mesh->vao.get(), mesh->vertices, mesh->count);
            !s)
            return s.error();
    }
    m->ranges = translucentRanges(clear);
    if (Status s = gl::checkError("uploading the sun-map occluders"); !s) return s.error();
    return std::unique_ptr<SceneOccluders>(new SceneOccluders(std::move(m)));
}

void SceneOccluders::draw(void* user, int, int, const float viewProjection[16], unsigned,
                          const int*) {
    const Impl& m = *static_cast<SceneOccluders*>(user)->m;
    const GLuint p = m.program.get();
    glProgramUniformMatrix4fv(p, m.viewProjection, 1, GL_FALSE, viewProjection);
    glUseProgram(p);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    if (m.opaque.count > 0) {
        glProgramUniform1f(p, m.keep, 0.f);
        glBindVertexArray(m.opaque.vao.get());
        glDrawArrays(GL_TRIANGLES, 0, m.opaque.count);
    }
    if (m.ranges.empty()) return;
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);  // the tile x (1 - opacity)
    glBindVertexArray(m.translucent.vao.get());
    drawTranslucent(m.ranges, [&](float opacity) { glProgramUniform1f(p, m.keep, 1.f - opacity); });
    glDisable(GL_BLEND);
}

}  // namespace flarekit
