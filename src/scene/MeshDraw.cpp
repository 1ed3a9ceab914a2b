// SPDX-License-Identifier: Apache-2.0
#include "scene/MeshDraw.h"

namespace flarekit {

Status uploadMesh(const std::vector<MeshVertex>& mesh, GLuint vao, gl::Buffer& vertices,
                  GLsizei& count) {
    vertices.reset();
    count = GLsizei(mesh.size());
    if (mesh.empty()) return Ok{};
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    vertices = gl::Buffer(buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(mesh.size() * sizeof(MeshVertex)), mesh.data(), 0);
    glVertexArrayVertexBuffer(vao, 0, buffer, 0, sizeof(MeshVertex));
    for (GLuint attr = 0; attr < 3; ++attr) {
        glEnableVertexArrayAttrib(vao, attr);
        glVertexArrayAttribFormat(vao, attr, 3, GL_FLOAT, GL_FALSE, attr * 3 * sizeof(float));
        glVertexArrayAttribBinding(vao, attr, 0);
    }
    return Ok{};
}

}  // namespace flarekit
