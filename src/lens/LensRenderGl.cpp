// SPDX-License-Identifier: Apache-2.0
// The OpenGL ghost rasteriser of `lens render --backend gl` (see flarekit/gl/GpuLens.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "core/Interrupt.h"
#include "flarekit/gl/GpuLens.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"
#include "lens/GhostMesh.h"

namespace flarekit {

namespace {

//! One vertex: pixel x, y; throughput, vignette, the three stop crossings; density.
constexpr int kFloatsPerVertex = 11;

void appendVertex(std::vector<float>& out, const lens::RayResult& r, double density, double x,
                  double y) {
    const float v[kFloatsPerVertex] = {float(x),          float(y),         float(r.throughput),
                                       float(r.vignette), float(r.stop[0]), float(r.stop[1]),
                                       float(r.stop[2]),  float(r.stop[3]), float(r.stop[4]),
                                       float(r.stop[5]),  float(density)};
    out.insert(out.end(), v, v + kFloatsPerVertex);
}

//! The centroid of a sub-pixel triangle, with its averaged attributes: what the CPU's point
//! path evaluates, at the centre of the pixel the CPU puts it in.
lens::RayResult centroid(const lens::RayResult& a, const lens::RayResult& b,
                         const lens::RayResult& c) {
    lens::RayResult m = a;
    m.x = std::floor((a.x + b.x + c.x) / 3) + 0.5, m.y = std::floor((a.y + b.y + c.y) / 3) + 0.5;
    m.throughput = (a.throughput + b.throughput + c.throughput) / 3;
    m.vignette = (a.vignette + b.vignette + c.vignette) / 3;
    for (std::size_t i = 0; i < m.stop.size(); ++i)
        m.stop[i] = (a.stop[i] + b.stop[i] + c.stop[i]) / 3;
    return m;
}

//! Meshes drawn between two fences: about 0.1 s each on llvmpipe for a spectral render's
//! meshes, so a signal waits for at most two batches (under 1 s); microseconds on a GPU.
constexpr std::size_t kMeshesPerFence = 4;

//! Keeps the GPU at most two fenced batches behind the CPU, waiting in 20 ms slices that poll
//! the interrupt flag.
class FenceThrottle {
  public:
    FenceThrottle() = default;
    FenceThrottle(const FenceThrottle&) = delete;
    FenceThrottle& operator=(const FenceThrottle&) = delete;
    ~FenceThrottle() {
        for (GLsync f : {m_older, m_newer})
            if (f) glDeleteSync(f);
    }
    //! A batch was queued: fence it, and wait for the one before it. False: interrupted.
    bool next() {
        if (!wait(m_older)) return false;
        m_older = m_newer;
        m_newer = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        return true;
    }
    //! Every batch done. False: interrupted.
    bool drain() { return next() && wait(m_older) && wait(m_newer); }

  private:
    static constexpr GLuint64 kSliceNs = 20'000'000;
    bool wait(GLsync& fence) {
        if (!fence) return true;
        for (;;) {
            const GLenum r = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, kSliceNs);
            if (r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED || r == GL_WAIT_FAILED)
                break;
            if (interrupted()) return false;
        }
        glDeleteSync(fence);
        fence = nullptr;
        return true;
    }
    GLsync m_older = nullptr, m_newer = nullptr;
};

class GlGhostDrawer final : public lens::GhostDrawer {
  public:
    static Result<std::unique_ptr<GlGhostDrawer>> create(int width, int height) {
        if (Status s = gl::requireCurrentContext("lens render --backend gl"); !s) return s.error();
        auto d = std::unique_ptr<GlGhostDrawer>(new GlGhostDrawer(width, height));
        while (d->m_side < std::max(width, height)) d->m_side *= 2;
        GLint dims[2] = {0, 0};
        glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
        if (d->m_side > std::min(dims[0], dims[1]))
            return invalidInput("lens render --backend gl: a " + std::to_string(width) + "x" +
                                std::to_string(height) + " frame needs a " +
                                std::to_string(d->m_side) +
                                " px square viewport, over this OpenGL's limit of " +
                                std::to_string(std::min(dims[0], dims[1])) +
                                " (GL_MAX_VIEWPORT_DIMS); use --backend cpu");
        auto program =
            gl::linkProgram({{GL_VERTEX_SHADER, "lens_ghost.vert", shaders::lens_ghost_vert},
                             {GL_GEOMETRY_SHADER, "lens_ghost.geom", shaders::lens_ghost_geom},
                             {GL_FRAGMENT_SHADER, "lens_ghost.frag", shaders::lens_ghost_frag}});
        if (!program) return program.error();
        d->m_program = std::move(*program);
        d->m_target = gl::makeTexture2D(GL_RGBA32F, width, height);
        auto fbo = gl::makeFramebuffer(d->m_target);
        if (!fbo) return fbo.error();
        d->m_fbo = std::move(*fbo);
        GLuint vao = 0, vbo = 0;
        glCreateVertexArrays(1, &vao);
        glCreateBuffers(1, &vbo);
        d->m_vao = gl::VertexArray(vao), d->m_vbo = gl::Buffer(vbo);
        glVertexArrayVertexBuffer(vao, 0, vbo, 0, kFloatsPerVertex * sizeof(float));
        const int sizes[] = {2, 4, 4, 1};
        int offset = 0;
        for (GLuint a = 0; a < 4; ++a) {
            glEnableVertexArrayAttrib(vao, a);
            glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE,
                                      GLuint(offset * sizeof(float)));
            glVertexArrayAttribBinding(vao, a, 0);
            offset += sizes[a];
        }
        const float clear[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(d->m_fbo.get(), GL_COLOR, 0, clear);
        glCreateQueries(GL_TIME_ELAPSED, 1, &vao);
        d->m_timer = gl::Query(vao);
        if (Status s = gl::checkError("lens render: GL set-up"); !s) return s.error();
        return d;
    }

    Status draw(const std::vector<lens::Mesh>& meshes, const lens::Iris& iris) override {
        const GLuint p = m_program.get();
        glUseProgram(p);
        glBindFramebuffer(GL_FRAMEBUFFER, m_fbo.get());
        // A square power-of-two viewport over the target (the attachment clips the rest): the
        // pixel-to-window map then divides and multiplies by powers of two only, exactly.
        const int side = m_side;
        glViewport(0, 0, side, side);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
        glBindVertexArray(m_vao.get());
        glProgramUniform1f(p, gl::uniformLocation(p, "u_side"), float(side));
        glProgramUniform1f(p, gl::uniformLocation(p, "u_height"), float(m_height));
        glProgramUniform1i(p, gl::uniformLocation(p, "u_blades"), iris.blades);
        glProgramUniform1f(p, gl::uniformLocation(p, "u_cosHalf"), float(iris.cosHalf));
        glProgramUniform1f(p, gl::uniformLocation(p, "u_roundness"), float(iris.roundness));
        glProgramUniform1f(p, gl::uniformLocation(p, "u_maskEdge"), float(lens::kMaskEdge));
        float normals[64];
        for (int i = 0; i < 64; ++i) normals[i] = float(iris.normals[std::size_t(i)]);
        glProgramUniform2fv(p, gl::uniformLocation(p, "u_normals"), 32, normals);
        const GLint weight = gl::uniformLocation(p, "u_weight"),
                    crossings = gl::uniformLocation(p, "u_crossings");
        glBeginQuery(GL_TIME_ELAPSED, m_timer.get());
        std::vector<float> triangles;
        // A signal stops the draw between meshes. The GPU runs behind the loop (llvmpipe draws
        // a spectral render's meshes for a minute after the loop has queued them all), so the
        // loop keeps at most two batches of kMeshesPerFence meshes queued, waiting for the older
        // batch's fence in short slices that poll the interrupt flag.
        FenceThrottle throttle;
        const auto stop = [&] {
            glEndQuery(GL_TIME_ELAPSED);
            glDisable(GL_BLEND);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            return interruptedError("lens render: the ghost draw was stopped");
        };
        for (std::size_t k = 0; k < meshes.size(); ++k) {
            const lens::Mesh& m = meshes[k];
            if (interrupted()) return stop();
            if (k % kMeshesPerFence == 0 && k > 0 && !throttle.next()) return stop();
            triangles.clear();
            int stopCrossings = 0;
            const auto add = [&](const lens::RayResult& a, const lens::RayResult& b,
                                 const lens::RayResult& c) {
                const lens::TrianglePlan plan = lens::planTriangle(m, iris, a, b, c);
                if (!plan.draw) return;
                stopCrossings = a.stopCrossings;
                if (plan.point) {
                    // A quarter-pixel triangle around the centre of the centroid's pixel: it
                    // covers that pixel centre and no other, with the averaged attributes.
                    const lens::RayResult mid = centroid(a, b, c);
                    appendVertex(triangles, mid, plan.density, mid.x - 0.25, mid.y - 0.25);
                    appendVertex(triangles, mid, plan.density, mid.x + 0.25, mid.y - 0.25);
                    appendVertex(triangles, mid, plan.density, mid.x, mid.y + 0.25);
                } else {
                    if (lens::insideImage(a, b, c, m_width, m_height)) {
                        for (const lens::RayResult* r : {&a, &b, &c})
                            appendVertex(triangles, *r, plan.density, r->x, r->y);
                        return;
                    }
                    for (const auto& piece : lens::clipToImage(a, b, c, m_width, m_height)) {
                        for (const lens::RayResult& r : piece)
                            appendVertex(triangles, r, plan.density, r.x, r.y);
                    }
                }
            };
            lens::forEachTriangle(m, add);
            if (triangles.empty()) continue;
            glProgramUniform3f(p, weight, float(m.weight[0]), float(m.weight[1]),
                               float(m.weight[2]));
            glProgramUniform1i(p, crossings, stopCrossings);
            glNamedBufferData(m_vbo.get(), GLsizeiptr(triangles.size() * sizeof(float)),
                              triangles.data(), GL_STREAM_DRAW);
            glDrawArrays(GL_TRIANGLES, 0, GLsizei(triangles.size() / kFloatsPerVertex));
        }
        if (!throttle.drain()) return stop();
        glEndQuery(GL_TIME_ELAPSED);
        GLuint64 ns = 0;
        glGetQueryObjectui64v(m_timer.get(), GL_QUERY_RESULT, &ns);
        m_gpuMs += double(ns) * 1e-6;
        glDisable(GL_BLEND);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return gl::checkError("lens render: ghost draw");
    }

    Status finish(Image& ghosts) override {
        const auto start = std::chrono::steady_clock::now();
        auto image = gl::readTextureRgba(m_target.get(), m_width, m_height);
        if (!image) return image.error();
        ghosts = std::move(*image);
        m_readbackMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        return Ok{};
    }

    double gpuMs() const { return m_gpuMs; }
    double readbackMs() const { return m_readbackMs; }

  private:
    GlGhostDrawer(int width, int height) : m_width(width), m_height(height) {}
    int m_width, m_height;
    int m_side = 1;  //!< the power-of-two viewport's side
    gl::Program m_program;
    gl::Texture m_target;
    gl::Framebuffer m_fbo;
    gl::VertexArray m_vao;
    gl::Buffer m_vbo;
    gl::Query m_timer;
    double m_gpuMs = 0, m_readbackMs = 0;
};

}  // namespace

Result<LensFlareLayers> renderLensFlareGl(const Lens& lens, int width, int height,
                                          const std::vector<LensLight>& lights,
                                          const LensRenderOptions& options, LensGlTimes* times) {
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
        return invalidInput("lens render: expected an image of 1 to " +
                            std::to_string(kMaxImageSide) + " pixels a side");
    auto drawer = GlGhostDrawer::create(width, height);
    if (!drawer) return drawer.error();
    auto layers = lens::renderLensFlareWith(lens, width, height, lights, options, **drawer);
    if (times) {
        times->ghostsGpuMs = (*drawer)->gpuMs();
        times->readbackMs = (*drawer)->readbackMs();
    }
    return layers;
}

}  // namespace flarekit
