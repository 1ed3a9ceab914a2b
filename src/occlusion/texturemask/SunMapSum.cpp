// SPDX-License-Identifier: Apache-2.0
#include "occlusion/texturemask/SunMapSum.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flarekit_shaders.h"
#include "occlusion/GpuMethod.h"

namespace flarekit::occlusion {

SceneCamera sunCamera(const Scene& view) {
    SceneCamera c = view.camera;
    const Vec3 s = normalize(view.sun.direction);
    c.lookAt = c.position + s;
    c.up = std::abs(s.y) < 0.99 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    c.fovYDeg = 2 * view.sun.angularRadiusDeg;  // the disc touches the viewport's edges
    if (view.sun.distance > 0) {  // a sphere light: only what lies before it may hide it
        c.farPlane = 0.999 * view.sun.distance;
        c.nearPlane = std::min(c.nearPlane, 0.5 * c.farPlane);
    }
    return c;
}

Result<SunMapLayout> sunMapLayout(const std::string& variant, int samples, bool fractional) {
    SunMapLayout l;
    l.msaaSamples = std::max(1, samples);
    l.fractional = fractional || l.msaaSamples > 1;
    if (variant == "square" || variant == "bilinear") {
        l.size = 16;
        l.bilinear = variant == "bilinear";
        if (l.bilinear) {
            l.unit = 4.f / 255.f;
            for (int j = 0; j < 8; ++j)
                for (int i = 0; i < 8; ++i)
                    l.samples.insert(l.samples.end(),
                                     {float(2 * i + 1) / 16.f, float(2 * j + 1) / 16.f});
        } else {
            for (int j = 0; j < 16; ++j)
                for (int i = 0; i < 16; ++i)
                    l.samples.insert(l.samples.end(),
                                     {(float(i) + 0.5f) / 16.f, (float(j) + 0.5f) / 16.f});
        }
        return l;
    }
    if (variant == "circle") {
        l.size = 18;
        if (l.fractional) {  // partial rim texels count by their G share: sum them all
            for (int j = 0; j < l.size; ++j)
                for (int i = 0; i < l.size; ++i)
                    l.samples.insert(l.samples.end(), {(float(i) + 0.5f) / float(l.size),
                                                       (float(j) + 0.5f) / float(l.size)});
            return l;
        }
        // The texels whose centre ray is in the disc, found with the shaders' own test on a
        // sun camera (its exact orientation does not matter: the disc is centred).
        Scene probe;
        probe.sun.direction = {0, 0, -1};
        probe.camera.position = {0, 0, 0};
        const SunDiscView v = sunDiscView(sunCamera(probe), l.size, l.size, probe.sun);
        for (int j = 0; j < l.size; ++j)
            for (int i = 0; i < l.size; ++i)
                if (inSunDisc(v, rayThrough(v, i + 0.5, j + 0.5)))
                    l.samples.insert(l.samples.end(), {(float(i) + 0.5f) / float(l.size),
                                                       (float(j) + 0.5f) / float(l.size)});
        if (l.samples.size() / 2 > 255) l.samples.resize(255 * 2);  // never past the 8-bit range
        return l;
    }
    return invalidInput("texture-mask variant: expected square, circle or bilinear, got '" +
                        variant + "'");
}

Result<SunMapSum> SunMapSum::create(SunMapLayout layout) {
    SunMapSum s;
    s.m_layout = std::move(layout);
    const int n = s.m_layout.size;
    const GLenum mapFormat = s.m_layout.fractional ? GL_RGBA16F : GL_RGBA8;
    s.m_map = gl::makeTexture2D(mapFormat, n, n);
    const GLint filter = s.m_layout.bilinear ? GL_LINEAR : GL_NEAREST;
    glTextureParameteri(s.m_map.get(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(s.m_map.get(), GL_TEXTURE_MAG_FILTER, filter);
    auto mapTarget = gl::makeFramebuffer(s.m_map);
    if (!mapTarget) return mapTarget.error();
    s.m_mapTarget = std::move(*mapTarget);
    if (s.m_layout.msaaSamples > 1) {
        GLuint ms = 0;
        glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &ms);
        s.m_msMap = gl::Texture(ms);
        glTextureStorage2DMultisample(ms, s.m_layout.msaaSamples, mapFormat, n, n, GL_TRUE);
        auto msTarget = gl::makeFramebuffer(ms);
        if (!msTarget) return msTarget.error();
        s.m_msTarget = std::move(*msTarget);
    }
    s.m_intensity = gl::makeTexture2D(s.m_layout.fractional ? GL_RGBA32F : GL_RGBA8, 1, 1);
    auto intensityTarget = gl::makeFramebuffer(s.m_intensity);
    if (!intensityTarget) return intensityTarget.error();
    s.m_intensityTarget = std::move(*intensityTarget);
    GLuint names[1];
    glCreateFramebuffers(1, names);
    s.m_coverageTarget = gl::Framebuffer(names[0]);
    glCreateBuffers(1, names);
    s.m_samples = gl::Buffer(names[0]);
    glNamedBufferStorage(names[0], GLsizeiptr(s.m_layout.samples.size() * sizeof(float)),
                         s.m_layout.samples.data(), 0);
    glCreateVertexArrays(1, names);
    s.m_vao = gl::VertexArray(names[0]);
    auto sum = gl::linkProgram({{GL_VERTEX_SHADER, "sum_points.vert", shaders::sum_points_vert},
                                {GL_FRAGMENT_SHADER, "sum_points.frag", shaders::sum_points_frag}});
    if (!sum) return sum.error();
    s.m_sum = std::move(*sum);
    auto resolve = linkFullscreen("resolve_ratio.frag", shaders::resolve_ratio_frag);
    if (!resolve) return resolve.error();
    s.m_resolve = std::move(*resolve);
    glProgramUniform1f(s.m_sum.get(), gl::uniformLocation(s.m_sum.get(), "unit"), s.m_layout.unit);
    glProgramUniform1i(s.m_sum.get(), gl::uniformLocation(s.m_sum.get(), "sunMap"), 0);
    return s;
}

Status SunMapSum::sumInto(GLuint coverage) {
    const int n = m_layout.size;
    if (m_layout.msaaSamples > 1)  // the multisample resolve averages each texel's samples
        glBlitNamedFramebuffer(m_msTarget.get(), m_mapTarget.get(), 0, 0, n, n, 0, 0, n, n,
                               GL_COLOR_BUFFER_BIT, GL_NEAREST);
    // Sum: every sample adds into the one texel of the intensity map.
    glBindFramebuffer(GL_FRAMEBUFFER, m_intensityTarget.get());
    glViewport(0, 0, 1, 1);
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glBindTextureUnit(0, m_map.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m_samples.get());
    glBindVertexArray(m_vao.get());
    glUseProgram(m_sum.get());
    glDrawArrays(GL_POINTS, 0, GLsizei(m_layout.samples.size() / 2));
    glDisable(GL_BLEND);
    // Resolve into the caller's coverage texture.
    if (m_coverageAttached != coverage) {
        glNamedFramebufferTexture(m_coverageTarget.get(), GL_COLOR_ATTACHMENT0, coverage, 0);
        m_coverageAttached = coverage;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, m_coverageTarget.get());
    glBindTextureUnit(0, m_intensity.get());
    glUseProgram(m_resolve.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return gl::checkError("texture mask: sum and resolve");
}

std::vector<MethodView> SunMapSum::views() const {
    const int n = m_layout.size;
    const std::string side = std::to_string(n);
    return {readMethodView(m_map.get(), n, n, "sun map " + side + "x" + side),
            readMethodView(m_intensity.get(), 1, 1, "intensity map 1x1")};
}

}  // namespace flarekit::occlusion
