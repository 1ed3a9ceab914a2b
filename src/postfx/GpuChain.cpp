// The OpenGL post-process chain: the wiring of Chain.cpp with one full-screen draw per pass.
// Every pass shader is postfx_common.glsl + its folder's .frag, reading the same uniforms the
// CPU kernel reads from ChainPlan. Textures are RGBA32F (half floats would cost the 1e-3
// parity) and image row y is GL row y, so gl_FragCoord.y - 0.5 is the CPU's y.
#include <chrono>

#include "flarekit/PostFx.h"
#include "flarekit_shaders.h"
#include "gl/GlObjects.h"
#include "postfx/ChainPlan.h"
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
           std::to_string(kMaxSpokes) + "\n#define FK_HALO_SAMPLES " + std::to_string(kHaloSamples) +
           "\n#define FK_STREAK_TAPS " + std::to_string(kStreakTaps) + "\n";
}

Result<gl::Program> linkPass(const char* name, std::initializer_list<const char*> parts) {
    std::string text = "#version 450 core\n" + sharedSizeDefines();
    text += shaders::postfx_common_glsl;
    for (const char* part : parts) text += part;
    return gl::linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert}, {GL_FRAGMENT_SHADER, name, text}});
}

GLint at(GLuint p, const char* name) { return gl::uniformLocation(p, name); }
void set(GLuint p, const char* name, float v) { glProgramUniform1f(p, at(p, name), v); }
void set(GLuint p, const char* name, int v) { glProgramUniform1i(p, at(p, name), v); }
void set(GLuint p, const char* name, Vec2 v) { glProgramUniform2f(p, at(p, name), v.x, v.y); }
void set(GLuint p, const char* name, const Rgb& v) { glProgramUniform3f(p, at(p, name), v[0], v[1], v[2]); }

}  // namespace

struct GpuPostFx::Impl {
    gl::Program bright, downsample, upsample, ghosts, halo, streaks, lens, composite;
    gl::VertexArray vao;
    Size input;
    std::size_t levelCount = 0;
    gl::Texture source;
    Target final, ghostsT, haloT, streaksT, rightT, pingT, lensT, dirtT;
    std::vector<Target> mips, ups;
    LensDirtCache dirt;

    Status allocate(const ChainPlan& plan);
    void draw(const Target& target, GLuint program, std::initializer_list<GLuint> textures) const;
};

Result<GpuPostFx> GpuPostFx::create() {
    auto m = std::make_unique<Impl>();
    struct Pass {
        gl::Program* program;
        const char* name;
        std::initializer_list<const char*> parts;
    };
    const Pass passes[] = {
        {&m->bright, "bright_pass.frag", {shaders::bright_pass_frag}},
        {&m->downsample, "downsample.frag", {shaders::downsample_frag}},
        {&m->upsample, "upsample.frag", {shaders::upsample_frag}},
        {&m->ghosts, "ghosts.frag", {shaders::ghosts_frag}},
        {&m->halo, "halo.frag", {shaders::halo_frag}},
        {&m->streaks, "streaks.frag", {shaders::streaks_frag}},
        {&m->lens, "lens.frag", {shaders::chromatic_glsl, shaders::starburst_glsl, shaders::lens_frag}},
        {&m->composite, "composite.frag", {shaders::tone_curves_glsl, shaders::tone_map_glsl, shaders::composite_frag}},
    };
    for (const Pass& pass : passes) {
        auto program = linkPass(pass.name, pass.parts);
        if (!program) return program.error();
        *pass.program = std::move(*program);
    }
    m->vao = gl::makeVertexArray();
    return GpuPostFx(std::move(m));
}

GpuPostFx::GpuPostFx(std::unique_ptr<Impl> impl) : m(std::move(impl)) {}
GpuPostFx::~GpuPostFx() = default;
GpuPostFx::GpuPostFx(GpuPostFx&&) noexcept = default;
GpuPostFx& GpuPostFx::operator=(GpuPostFx&&) noexcept = default;

Status GpuPostFx::Impl::allocate(const ChainPlan& plan) {
    if (input.width == plan.input.width && input.height == plan.input.height && levelCount == plan.levels.size()) return Ok{};
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (plan.input.width > maxSize || plan.input.height > maxSize) {
        return invalidInput("postfx --backend gl: image " + std::to_string(plan.input.width) + "x" + std::to_string(plan.input.height) +
                            " exceeds this GL's GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize) + " (use --backend cpu)");
    }
    source = gl::makeTexture2D(GL_RGBA32F, plan.input.width, plan.input.height);
    const auto make = [](Size s, Target& t) -> Status {
        auto r = makeTarget(s);
        if (!r) return r.error();
        t = std::move(*r);
        return Ok{};
    };
    if (Status s = make(plan.input, final); !s) return s;
    mips.clear(), ups.clear();
    mips.resize(plan.levels.size()), ups.resize(plan.levels.size());
    for (std::size_t i = 0; i < plan.levels.size(); ++i) {
        if (Status s = make(plan.levels[i], mips[i]); !s) return s;
        if (i >= kWorkLevel && i + 1 < plan.levels.size()) {
            if (Status s = make(plan.levels[i], ups[i]); !s) return s;
        }
    }
    for (Target* t : {&ghostsT, &haloT, &streaksT, &rightT, &pingT, &lensT, &dirtT}) {
        if (Status s = make(plan.work(), *t); !s) return s;
    }
    input = plan.input, levelCount = plan.levels.size();
    dirt.invalidate();
    return gl::checkError("allocating the post-process targets");
}

void GpuPostFx::Impl::draw(const Target& target, GLuint program, std::initializer_list<GLuint> textures) const {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.get());
    glViewport(0, 0, target.size.width, target.size.height);
    GLuint unit = 0;
    for (GLuint t : textures) glBindTextureUnit(unit++, t);
    glUseProgram(program);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

namespace {

void clear(const Target& t) {
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(t.texture.get(), 0, GL_RGBA, GL_FLOAT, zero);
}

//! Times a group of draws with a timer query and, around glFinish, the wall clock.
class GlClock {
public:
    explicit GlClock(std::vector<PassTime>* times) : m_clock(times), m_on(times != nullptr) {}
    template <typename Work>
    void run(const char* pass, Size written, const Work& work) {
        if (!m_on) return work();
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        m_query.begin();
        work();
        m_query.end();
        glFinish();
        const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        m_clock.add(pass, written, m_query.milliseconds(), wall);
    }

private:
    PassClock m_clock;
    bool m_on;
    gl::TimerQuery m_query;
};

}  // namespace

Result<PostFxResult> GpuPostFx::run(const Image& input, const PostFxParams& params, const PostFxOptions& options) {
    auto planned = planChain(input.width(), input.height(), params);
    if (!planned) return planned.error();
    const ChainPlan& plan = *planned;
    if (Status s = m->allocate(plan); !s) return s.error();
    Impl& g = *m;
    const Size work = plan.work();
    glDisable(GL_BLEND), glDisable(GL_DEPTH_TEST), glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(g.vao.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(g.source.get(), 0, 0, 0, input.width(), input.height(), GL_RGBA, GL_FLOAT, input.data());
    if (plan.dirtOn() && g.dirt.update(work.width, work.height, plan.dirt)) {
        glTextureSubImage2D(g.dirtT.texture.get(), 0, 0, 0, work.width, work.height, GL_RGBA, GL_FLOAT, g.dirt.image().data());
    }
    GlClock clock(options.times);

    // 1. Bright pass and downsample chain.
    clock.run("bright", plan.levels[0], [&] {
        const GLuint p = g.bright.get();
        set(p, "threshold", plan.bright.threshold), set(p, "knee", plan.bright.knee), set(p, "invOutSize", plan.bright.invOutSize);
        g.draw(g.mips[0], p, {g.source.get()});
    });
    clock.run("downsample", plan.levels[1], [&] {
        const GLuint p = g.downsample.get();
        for (std::size_t i = 0; i < plan.down.size(); ++i) {
            set(p, "invOutSize", plan.down[i].invOutSize), set(p, "srcTexel", plan.down[i].srcTexel);
            g.draw(g.mips[i + 1], p, {g.mips[i].texture.get()});
        }
    });

    // 2. Blur: tent upsample to the bloom buffer (the coarsest level is its own U).
    const auto upTexture = [&](std::size_t level) {
        return level + 1 == plan.levels.size() ? g.mips[level].texture.get() : g.ups[level].texture.get();
    };
    clock.run("upsample", work, [&] {
        const GLuint p = g.upsample.get();
        for (std::size_t i = plan.up.size(); i-- > 0;) {
            const UpsampleUniforms& u = plan.up[i];
            set(p, "invOutSize", u.invOutSize), set(p, "coarseTexel", u.coarseTexel), set(p, "spread", u.spread), set(p, "scale", u.scale);
            g.draw(g.ups[i + 1], p, {g.mips[i + 1].texture.get(), upTexture(i + 2)});
        }
    });
    const GLuint bloom = upTexture(kWorkLevel);

    // 3. Ghosts and halo; 4. streaks.
    if (plan.ghostsOn()) {
        clock.run("ghosts", work, [&] {
            const GLuint p = g.ghosts.get();
            const GhostsUniforms& u = plan.ghosts;
            set(p, "invOutSize", u.invOutSize), set(p, "sourceTexel", u.sourceTexel), set(p, "intensity", u.intensity);
            set(p, "ghostCount", int(u.ghosts.size()));
            for (std::size_t i = 0; i < u.ghosts.size(); ++i) {
                const GhostParams& gh = u.ghosts[i];
                const auto name = [i](const char* array) { return std::string(array).append("[").append(std::to_string(i)).append("]"); };
                set(p, name("tints").c_str(), gh.tint), set(p, name("scales").c_str(), gh.scale);
                set(p, name("blurs").c_str(), gh.blur), set(p, name("thresholds").c_str(), gh.threshold);
                set(p, name("falloffs").c_str(), gh.falloff), set(p, name("sampleCounts").c_str(), gh.samples);
                set(p, name("centered").c_str(), int(gh.centered)), set(p, name("useBilinear").c_str(), int(gh.linearFilter));
            }
            g.draw(g.ghostsT, p, {bloom});
        });
    } else {
        clear(g.ghostsT);
    }
    if (plan.haloOn()) {
        clock.run("halo", work, [&] {
            const GLuint p = g.halo.get();
            const HaloUniforms& u = plan.halo;
            set(p, "invOutSize", u.invOutSize), set(p, "aspect", u.aspect), set(p, "radius", u.halo.radius);
            set(p, "thickness", u.halo.thickness), set(p, "threshold", u.halo.threshold), set(p, "falloff", u.halo.falloff);
            set(p, "intensity", u.intensity), set(p, "tint", u.halo.tint);
            g.draw(g.haloT, p, {bloom});
        });
    } else {
        clear(g.haloT);
    }
    if (plan.streaksOn()) {
        clock.run("streaks", work, [&] {
            const GLuint p = g.streaks.get();
            const auto chain = [&](const std::vector<StreakUniforms>& passes, const Target& last) {
                GLuint src = g.mips[kWorkLevel].texture.get();
                for (std::size_t i = 0; i < passes.size(); ++i) {
                    const StreakUniforms& u = passes[i];
                    const Target& dst = (passes.size() - i) % 2 == 1 ? last : g.pingT;
                    set(p, "step", u.step), set(p, "threshold", u.threshold), set(p, "addOther", int(u.addOther));
                    glProgramUniform1fv(p, at(p, "weights"), GLsizei(u.weights.size()), u.weights.data());
                    glProgramUniform4f(p, at(p, "outScale"), u.outScale[0], u.outScale[1], u.outScale[2], u.outScale[3]);
                    g.draw(dst, p, {src, u.addOther ? g.rightT.texture.get() : 0u});
                    src = dst.texture.get();
                }
            };
            chain(plan.streaks.right, g.rightT);
            chain(plan.streaks.left, g.streaksT);
        });
    } else {
        clear(g.streaksT);
    }

    // 5. Lens buffer and the full-resolution composite.
    clock.run("lens", work, [&] {
        const GLuint p = g.lens.get();
        const LensUniforms& u = plan.lens;
        set(p, "invOutSize", u.invOutSize), set(p, "aspect", u.aspect), set(p, "bloomIntensity", u.bloomIntensity);
        set(p, "chromatic", u.chromatic), set(p, "dirtIntensity", u.dirtIntensity);
        set(p, "starIntensity", u.star.intensity), set(p, "starWidth", u.star.width), set(p, "starSpokes", u.star.spokes);
        glProgramUniform1fv(p, at(p, "starRays"), GLsizei(u.star.rays.size()), u.star.rays.data());
        g.draw(g.lensT, p, {bloom, g.ghostsT.texture.get(), g.haloT.texture.get(), g.streaksT.texture.get(), g.dirtT.texture.get()});
    });
    clock.run("composite", plan.input, [&] {
        const GLuint p = g.composite.get();
        set(p, "invOutSize", plan.composite.invOutSize), set(p, "toneOperator", plan.composite.toneOperator);
        set(p, "exposure", plan.composite.exposure);
        g.draw(g.final, p, {g.source.get(), g.lensT.texture.get()});
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
    if (Status s = read(g.final, result.final); !s) return s.error();
    if (options.keepLayers) {
        for (auto [t, out] : {std::pair{&g.ghostsT, &result.ghosts}, std::pair{&g.haloT, &result.halo},
                              std::pair{&g.streaksT, &result.streaks}, std::pair{&g.lensT, &result.lens}}) {
            if (Status s = read(*t, *out); !s) return s.error();
        }
        auto b = gl::readTextureRgba(bloom, work.width, work.height, false);
        if (!b) return b.error();
        result.bloom = std::move(*b);
        scaleInPlace(result.bloom, params.bloom.intensity);
    }
    return result;
}

}  // namespace flarekit
