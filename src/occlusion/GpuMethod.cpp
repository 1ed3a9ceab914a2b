// SPDX-License-Identifier: Apache-2.0
#include "occlusion/GpuMethod.h"

#include <algorithm>
#include <vector>

#include "flarekit_shaders.h"

namespace flarekit::occlusion {

GpuMethod::GpuMethod() : m_coverage(gl::makeTexture2D(GL_R32F, 1, 1)) {
    glTextureParameteri(m_coverage.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(m_coverage.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    const float zero = 0.f;
    glTextureSubImage2D(m_coverage.get(), 0, 0, 0, 1, 1, GL_RED, GL_FLOAT, &zero);
}

void GpuMethod::publish(double coverage) {
    const float value = float(coverage);
    glTextureSubImage2D(m_coverage.get(), 0, 0, 0, 1, 1, GL_RED, GL_FLOAT, &value);
    m_hasResult = true;
}

std::optional<double> GpuMethod::latestCoverage() {
    if (!m_hasResult) return std::nullopt;
    float value = 0;
    glGetTextureImage(m_coverage.get(), 0, GL_RED, GL_FLOAT, sizeof value, &value);
    return double(value);
}

MethodView readMethodView(GLuint texture, int width, int height, std::string name) {
    std::vector<float> texels(std::size_t(width) * std::size_t(height) * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)),
                      texels.data());
    MethodView view{std::move(name), Image(width, height)};
    const std::size_t rowFloats = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(texels.data() + std::size_t(height - 1 - y) * rowFloats, rowFloats,
                    view.image.row(y));
    return view;
}

namespace {
//! The shader files start with their own #version line: it is replaced by `prelude` (which
//! starts with #version), and "#line 2" keeps the driver's line numbers those of the file.
std::string withPrelude(std::string text, const std::string& prelude) {
    if (text.rfind("#version", 0) == 0) text = text.substr(text.find('\n') + 1);
    return prelude + "\n#line 2\n" + text;
}
}  // namespace

Result<gl::Program> linkWithDisc(std::initializer_list<gl::ShaderSource> sources,
                                 const std::string& defines) {
    const std::string prelude =
        std::string("#version 450 core\n") + defines + shaders::sun_disc_glsl;
    std::vector<gl::ShaderSource> full;
    for (const gl::ShaderSource& s : sources)
        full.push_back({s.stage, s.name, withPrelude(s.text, prelude)});
    switch (full.size()) {
        case 1:
            return gl::linkProgram({full[0]});
        case 2:
            return gl::linkProgram({full[0], full[1]});
        default:
            return internalError("linkWithDisc: one or two shaders");
    }
}

Result<gl::Program> linkFullscreen(const std::string& fragmentName, const char* fragmentText,
                                   const std::string& defines) {
    return gl::linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", shaders::fullscreen_vert},
                            {GL_FRAGMENT_SHADER, fragmentName,
                             withPrelude(fragmentText, "#version 450 core\n" + defines)}});
}

}  // namespace flarekit::occlusion
