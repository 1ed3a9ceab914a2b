// SPDX-License-Identifier: Apache-2.0
// The GL executor of the post-process chain: every step of the plan is one full-screen draw
// of its pass's program into the step's target, with its inputs bound to texture units in
// order and its uniforms set by the pass's own bindUniforms. Each program is postfx_common.glsl
// + the pass folder's shader (*Gl.h), after the sizes C++ and GLSL share as #defines. Textures
// are RGBA32F (half floats would cost the 1e-3 parity) and image row y is GL row y, so
// gl_FragCoord.y - 0.5 is the CPU's y. The input and the result move through pixel buffers
// (gl/PixelTransfer.h), as halves where that loses nothing (PostFxOptions).
#include <chrono>

#include "flarekit/PostFx.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"
#include "gl/PixelTransfer.h"
#include "postfx/ChainPlan.h"
#include "postfx/PassClock.h"
#include "postfx/PassShaders.h"
#include "postfx/dirt/LensDirtCache.h"

namespace flarekit {

using namespace postfx;

namespace {

struct Target {
    Size size;
    gl::Texture texture;
    gl::Framebuffer framebuffer;
};

Result<Target> makeTarget(Size size) {
    Target t{size, gl::makeTexture2D(GL_RGBA32F, size.width, size.height), {}};
    auto fb = gl::makeFramebuffer(t.texture);
    if (!fb) return fb.error();
    t.framebuffer = std::move(*fb);
    return t;
}

//! The sizes C++ and GLSL share, defined once in C++ and handed to every pass shader.
std::string sharedSizeDefines() {
    return "#define FK_MAX_GHOSTS " + std::to_string(kMaxGhosts) + "\n#define FK_MAX_SPOKES " +
           std::to_string(kMaxSpokes) + "\n#define FK_MAX_STAR_CENTRES " +
           std::to_string(kMaxStarCentres) + "\n#define FK_HALO_SAMPLES " +
           std::to_string(kHaloSamples) + "\n#define FK_STREAK_TAPS " +
           std::to_string(kStreakTaps) + "\n";
}

Result<gl::Program> linkPass(const PassShader& shader) {
    std::string text = "#version 450 core\n" + sharedSizeDefines();
    text += shaders::postfx_common_glsl;
    for (const char* part : shader.parts) text += part;
    return gl::linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                            {GL_FRAGMENT_SHADER, shader.name, text}});
}

//! The uniform setter a pass's bindUniforms writes through (a misspelt name is an error:
//! gl::uniformLocation).
struct GlUniforms {
    GLuint p;
    GLint at(const char* name) const { return gl::uniformLocation(p, name); }
    void set(const char* name, float v) const { glProgramUniform1f(p, at(name), v); }
    void set(const char* name, int v) const { glProgramUniform1i(p, at(name), v); }
    void set(const char* name, Vec2 v) const { glProgramUniform2f(p, at(name), v.x, v.y); }
    void set(const char* name, const Rgb& v) const {
        glProgramUniform3f(p, at(name), v[0], v[1], v[2]);
    }
    void set(const char* name, F4 v) const {
        glProgramUniform4f(p, at(name), v[0], v[1], v[2], v[3]);
    }
    void set(const char* name, std::span<const float> v) const {
        glProgramUniform1fv(p, at(name), GLsizei(v.size()), v.data());
    }
    void set(const char* name, std::span<const Vec2> v) const {
        static_assert(sizeof(Vec2) == 2 * sizeof(float));
        glProgramUniform2fv(p, at(name), GLsizei(v.size()), &v.data()->x);
    }
};

void clear(const Target& t) {
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(t.texture.get(), 0, GL_RGBA, GL_FLOAT, zero);
}

//! Times a group of draws with a timer query and, around glFinish, the wall clock.
class GlClock {
  public:
    explicit GlClock(std::vector<PassTime>* times) : m_clock(times) {}
    template <typename Work>
    void run(const char* pass, Size written, const Work& work) {
        if (!m_clock.on()) return work();
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        m_query.begin();
        work();
        m_query.end();
        glFinish();
        const double wall =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        m_clock.add(pass, written, m_query.milliseconds(), wall);
    }

  private:
    PassClock m_clock;
    gl::TimerQuery m_query;
};

template <std::size_t... I>
Status linkAll(std::vector<gl::Program>& programs, std::index_sequence<I...>) {
    Status status = Ok{};
    const auto one = [&](auto type) {
        using U = typename decltype(type)::type;
        if constexpr (std::is_same_v<U, ClearStep>) {
            programs.emplace_back();  // a clear draws nothing
        } else if (status) {
            auto program = linkPass(passShader(std::type_identity<U>{}));
            if (!program)
                status = program.error();
            else
                programs.push_back(std::move(*program));
        }
    };
    (one(std::type_identity<std::variant_alternative_t<I, PassUniforms>>{}), ...);
    return status;
}

}  // namespace

struct GpuPostFx::Impl {
    std::vector<gl::Program> programs;  //!< one per PassUniforms alternative
    gl::VertexArray vao;
    Size input;
    std::size_t levelCount = 0;
    bool halfSource = false;
    gl::Texture source;
    gl::PixelTransfer transfer;
    Target final, dirtT;
    ChainBuffers<Target> buffers;
    LensDirtCache dirt;

    Status allocate(const ChainPlan& plan, bool half);
    GLuint texture(BufferId id) const;
    const Target& target(BufferId id) const;
    void execute(const Step& step) const;
};

Result<GpuPostFx> GpuPostFx::create() {
    if (Status s = gl::requireCurrentContext("GpuPostFx::create"); !s) return s.error();
    auto m = std::make_unique<Impl>();
    if (Status s =
            linkAll(m->programs, std::make_index_sequence<std::variant_size_v<PassUniforms>>{});
        !s) {
        return s.error();
    }
    m->vao = gl::makeVertexArray();
    return GpuPostFx(std::move(m));
}

GpuPostFx::GpuPostFx(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
GpuPostFx::~GpuPostFx() = default;
GpuPostFx::GpuPostFx(GpuPostFx&&) noexcept = default;
GpuPostFx& GpuPostFx::operator=(GpuPostFx&&) noexcept = default;

Status GpuPostFx::Impl::allocate(const ChainPlan& plan, bool half) {
    if (input.width == plan.input.width && input.height == plan.input.height &&
        levelCount == plan.levels.size()) {
        if (half != halfSource) {
            source = gl::makeTexture2D(half ? GL_RGBA16F : GL_RGBA32F, input.width, input.height);
            halfSource = half;
        }
        return gl::checkError("allocating the post-process input");
    }
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (plan.input.width > maxSize || plan.input.height > maxSize) {
        return invalidInput("postfx --backend gl: image " + std::to_string(plan.input.width) + "x" +
                            std::to_string(plan.input.height) +
                            " exceeds this GL's GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize) +
                            " (use --backend cpu)");
    }
    source = gl::makeTexture2D(half ? GL_RGBA16F : GL_RGBA32F, plan.input.width, plan.input.height);
    halfSource = half;
    const auto make = [](Size s, Target& t) -> Status {
        auto r = makeTarget(s);
        if (!r) return r.error();
        t = std::move(*r);
        return Ok{};
    };
    if (Status s = make(plan.input, final); !s) return s;
    ChainBuffers<Target>& b = buffers;
    b.mips.clear(), b.ups.clear();
    b.mips.resize(plan.levels.size()), b.ups.resize(plan.levels.size());
    for (std::size_t i = 0; i < plan.levels.size(); ++i) {
        if (Status s = make(plan.levels[i], b.mips[i]); !s) return s;
        if (i >= kWorkLevel && i + 1 < plan.levels.size()) {
            if (Status s = make(plan.levels[i], b.ups[i]); !s) return s;
        }
    }
    // The dirt texture is made when a preset first uses dirt (most do not).
    dirtT = {};
    for (Target* t : {&b.ghosts, &b.halo, &b.streaks, &b.right, &b.ping, &b.lens}) {
        if (Status s = make(plan.work(), *t); !s) return s;
    }
    input = plan.input, levelCount = plan.levels.size();
    dirt.invalidate();
    return gl::checkError("allocating the post-process targets");
}

const Target& GpuPostFx::Impl::target(BufferId id) const {
    if (id.kind == BufferKind::Dirt) return dirtT;
    if (const Target* t = buffers.find(id)) return *t;
    return final;  // Final (Input is read as the source texture)
}

GLuint GpuPostFx::Impl::texture(BufferId id) const {
    return id.kind == BufferKind::Input ? source.get() : target(id).texture.get();
}

void GpuPostFx::Impl::execute(const Step& step) const {
    const Target& out = target(step.output);
    if (std::holds_alternative<ClearStep>(step.uniforms)) return clear(out);
    const GLuint p = programs[step.uniforms.index()].get();
    std::visit(
        [&](const auto& u) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(u)>, ClearStep>) {
                GlUniforms sink{p};
                bindUniforms(u, sink);
            }
        },
        step.uniforms);
    glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer.get());
    glViewport(0, 0, out.size.width, out.size.height);
    GLuint unit = 0;
    for (BufferId id : step.inputs) glBindTextureUnit(unit++, texture(id));
    glUseProgram(p);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    for (GLuint u = 0; u < unit; ++u) glBindTextureUnit(u, 0);  // no target stays bound as an input
}

Result<PostFxResult> GpuPostFx::run(const Image& input, const PostFxParams& params,
                                    const PostFxOptions& options) {
    auto planned = planChain(input.width(), input.height(), fitToFrame(params, input));
    if (!planned) return planned.error();
    const ChainPlan& plan = *planned;
    if (Status s = m->allocate(plan, options.halfInput); !s) return s.error();
    Impl& g = *m;
    const Size work = plan.work();
    glDisable(GL_BLEND), glDisable(GL_DEPTH_TEST), glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(g.vao.get());
    GlClock clock(options.times);
    Status moved = Ok{};
    clock.run("upload", plan.input,
              [&] { moved = g.transfer.upload(g.source.get(), input, options.halfInput); });
    if (!moved) return moved.error();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (plan.dirtOn && !g.dirtT.texture) {
        auto t = makeTarget(work);
        if (!t) return t.error();
        g.dirtT = std::move(*t);
        g.dirt.invalidate();
    }
    if (plan.dirtOn && g.dirt.update(work.width, work.height, plan.dirt)) {
        glTextureSubImage2D(g.dirtT.texture.get(), 0, 0, 0, work.width, work.height, GL_RGBA,
                            GL_FLOAT, g.dirt.image().data());
    }
    forEachGroup(
        plan, [&](const char* label, Size written, std::size_t first, std::size_t last, bool off) {
            const auto group = [&] {
                for (std::size_t i = first; i < last; ++i) g.execute(plan.steps[i]);
            };
            off ? group() : clock.run(label, written, group);
        });
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (Status s = gl::checkError("post-process chain"); !s) return s.error();

    PostFxResult result;
    const auto read = [](const Target& t, Image& out) -> Status {
        auto image = gl::readTextureRgba(t.texture.get(), t.size.width, t.size.height, false);
        if (!image) return image.error();
        out = std::move(*image);
        return Ok{};
    };
    clock.run("read-back", plan.input, [&] {
        moved = g.transfer.download(g.final.texture.get(), g.final.size.width, g.final.size.height,
                                    options.halfReadback, result.final);
    });
    if (!moved) return moved.error();
    if (options.keepLayers) {
        const ChainBuffers<Target>& l = g.buffers;
        for (auto [t, out] :
             {std::pair{&l.ghosts, &result.ghosts}, std::pair{&l.halo, &result.halo},
              std::pair{&l.streaks, &result.streaks}, std::pair{&l.lens, &result.lens}}) {
            if (Status s = read(*t, *out); !s) return s.error();
        }
        if (Status s = read(g.target(plan.bloom), result.bloom); !s) return s.error();
        result.bloom.scale(params.bloom.intensity);
    }
    return result;
}

}  // namespace flarekit
