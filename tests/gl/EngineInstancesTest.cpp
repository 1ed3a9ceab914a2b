// SPDX-License-Identifier: Apache-2.0
// The any-renderer API: fk_flare_set's instance records, drawn with the exported GLSL shader
// the way a renderer of its own would draw them, against fk_engine_draw of the same lights and
// coverage (within one 8-bit level); presets from memory; the exported SPIR-V, HLSL and MSL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "../TempDir.h"
#include "DepthPass.h"
#include "EngineTesting.h"
#include "LightScenes.h"
#include "flarekit/flarekit.h"
#include "gl/GlObjects.h"

using namespace flarekit;
using namespace flarekit::test;

namespace {

//! A preset with an edge streak (quarter-turned on side edges) and a ring, as JSON text.
constexpr const char* kEdgePreset =
    R"({"name": "edge-and-ring", "elements": [)"
    R"({"type": "edge-streak", "size": 0.2, "aspect": 6, "reach": 0.6, "intensity": 0.8},)"
    R"({"type": "ring", "t": -0.6, "size": 0.08, "intensity": 0.5}]})";

struct SetDeleter {
    void operator()(fk_flare_set* s) const { fk_flare_set_destroy(s); }
};
using SetPtr = std::unique_ptr<fk_flare_set, SetDeleter>;

std::string shaderText(fk_shader_language language, fk_shader_stage stage) {
    std::size_t size = 0;
    const void* text = fk_flare_shader(language, stage, &size);
    EXPECT_NE(text, nullptr);
    return text ? std::string(static_cast<const char*>(text), size) : std::string();
}

//! What a renderer of its own does with the records: the sprites as textures, then per run
//! of one sprite slot an instanced strip of four vertices, blended additively.
void drawRecords(fk_flare_set* set, int slots, const std::vector<fk_flare_instance>& records,
                 const fk_frame& frame, GLuint framebuffer) {
    std::vector<gl::Texture> sprites;
    for (int slot = 0; slot < slots; ++slot) {
        int w = 0, h = 0;
        ASSERT_EQ(fk_flare_set_texture(set, slot, &w, &h, nullptr), 0);
        std::vector<float> rgba(std::size_t(w) * h * 4);
        ASSERT_EQ(fk_flare_set_texture(set, slot, &w, &h, rgba.data()), 0);
        gl::Texture t = gl::makeTexture2D(GL_RGBA32F, w, h);
        glTextureSubImage2D(t.get(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
        glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        sprites.push_back(std::move(t));
    }
    auto program = gl::linkProgram(
        {{GL_VERTEX_SHADER, "flare_instance.vert", shaderText(FK_SHADER_GLSL, FK_SHADER_VERTEX)},
         {GL_FRAGMENT_SHADER, "flare_instance.frag",
          shaderText(FK_SHADER_GLSL, FK_SHADER_FRAGMENT)}});
    ASSERT_TRUE(program.ok()) << program.error().message;
    GLuint buffers[2] = {0, 0};
    glCreateBuffers(2, buffers);
    glNamedBufferStorage(buffers[0], GLsizeiptr(records.size() * sizeof(fk_flare_instance)),
                         records.data(), 0);
    glNamedBufferStorage(buffers[1], 16, nullptr, GL_DYNAMIC_STORAGE_BIT);
    gl::VertexArray vao = gl::makeVertexArray();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(frame.viewport[0], frame.viewport[1], frame.viewport[2], frame.viewport[3]);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    glUseProgram(program->get());
    glBindVertexArray(vao.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
    glBindBufferBase(GL_UNIFORM_BUFFER, 1, buffers[1]);
    for (std::size_t first = 0; first < records.size();) {
        std::size_t end = first;
        while (end < records.size() && records[end].texture == records[first].texture) ++end;
        struct {
            float size[2], ySign;
            int firstInstance;
        } block{{float(frame.viewport[2]), float(frame.viewport[3])}, 1.f, int(first)};
        glNamedBufferSubData(buffers[1], 0, sizeof block, &block);
        glBindTextureUnit(2, sprites[std::size_t(records[first].texture)].get());
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(end - first));
        first = end;
    }
    glDisable(GL_BLEND);
    glUseProgram(0);
    glDeleteBuffers(2, buffers);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

std::vector<float> readColor(GLuint texture, int w, int h) {
    std::vector<float> pixels(std::size_t(w) * h * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                      pixels.data());
    return pixels;
}

//! An 8-bit level of a linear HDR value after a Reinhard tone map, the way it is viewed.
int level(float v) {
    const double x = std::max(0.0, double(v));
    return int(std::lround(255.0 * x / (1.0 + x)));
}

}  // namespace

TEST(EngineInstances, RecordsDrawnWithTheExportedShaderMatchTheEnginesDrawWithinOneLevel) {
    Scene scene = lampScene(64, 13, false, 960, 540);
    EnginePtr e = makeEngine(64);
    const int subtle = fk_engine_load_preset(e.get(), "subtle");
    const int edge = fk_engine_load_preset_json(e.get(), kEdgePreset, std::strlen(kEdgePreset));
    ASSERT_EQ(subtle, 0) << fk_error(e.get());
    ASSERT_EQ(edge, 1) << fk_error(e.get());
    std::vector<fk_light> lights = engineLights(scene, subtle);
    for (std::size_t i = 0; i < lights.size(); i += 3) lights[i].preset = edge;
    lights[5].preset = -1;  // no flare
    const DepthPass pass(scene);
    const DepthTarget target = makeDepthTarget(scene.width, scene.height, 1, GL_DEPTH_COMPONENT32F);
    const fk_frame frame =
        frameFor(scene, target, {0, 0, scene.width, scene.height}, FK_DEPTH_ZERO_TO_ONE);
    pass.draw(target, frame);
    ASSERT_EQ(fk_engine_occlusion(e.get(), &frame, lights.data(), 64), 0) << fk_error(e.get());
    std::vector<float> coverage(64);
    ASSERT_EQ(fk_engine_read_view(e.get(), 0, nullptr, nullptr, coverage.data(), 64), 64);
    const float black[4] = {0, 0, 0, 0};
    gl::Texture engineColor = gl::makeTexture2D(GL_RGBA32F, scene.width, scene.height);
    gl::Texture recordColor = gl::makeTexture2D(GL_RGBA32F, scene.width, scene.height);
    auto engineFb = gl::makeFramebuffer(engineColor.get());
    auto recordFb = gl::makeFramebuffer(recordColor.get());
    ASSERT_TRUE(engineFb.ok() && recordFb.ok());
    glClearNamedFramebufferfv(engineFb->get(), GL_COLOR, 0, black);
    glClearNamedFramebufferfv(recordFb->get(), GL_COLOR, 0, black);
    ASSERT_EQ(fk_engine_draw(e.get(), &frame, lights.data(), 64, engineFb->get()), 0)
        << fk_error(e.get());

    // The same presets in a flare set: one by name, one from memory, no GL needed for either.
    SetPtr set(fk_flare_set_create());
    ASSERT_EQ(fk_flare_set_load_preset(set.get(), "subtle"), 0) << fk_flare_set_error(set.get());
    ASSERT_EQ(fk_flare_set_load_preset_json(set.get(), kEdgePreset, std::strlen(kEdgePreset)), 1);
    const int slots = fk_flare_set_prepare(set.get(), scene.height);
    ASSERT_GT(slots, 4) << fk_flare_set_error(set.get());
    const int count = fk_flare_set_instances(set.get(), &frame, lights.data(), coverage.data(), 64,
                                             0.08f, nullptr, 0);
    ASSERT_GT(count, 100) << fk_flare_set_error(set.get());
    std::vector<fk_flare_instance> records(static_cast<std::size_t>(count));
    ASSERT_EQ(fk_flare_set_instances(set.get(), &frame, lights.data(), coverage.data(), 64, 0.08f,
                                     records.data(), count),
              count);
    int turned = 0, hidden = 0;
    for (const fk_flare_instance& r : records) {
        EXPECT_NE(r.light, 5);
        EXPECT_EQ(r.preset, lights[std::size_t(r.light)].preset);
        turned += r.rotation != 0.f ? 1 : 0;
    }
    for (int i = 0; i < 64; ++i) hidden += coverage[std::size_t(i)] == 0.f ? 1 : 0;
    EXPECT_GT(turned, 0);  // edge streaks on side edges
    EXPECT_GT(hidden, 0);  // fully hidden lights get no record
    drawRecords(set.get(), slots, records, frame, recordFb->get());

    const std::vector<float> a = readColor(engineColor.get(), scene.width, scene.height);
    const std::vector<float> b = readColor(recordColor.get(), scene.width, scene.height);
    int worst = 0;
    double lit = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (i % 4 == 3) continue;
        worst = std::max(worst, std::abs(level(a[i]) - level(b[i])));
        lit += level(a[i]) > 2 ? 1 : 0;
    }
    EXPECT_LE(worst, 1);
    EXPECT_GT(lit, 0.05 * scene.width * scene.height);  // the flares cover the frame's share
}

TEST(EngineInstances, BadArgumentsNameTheArgumentAndWriteNothing) {
    EXPECT_LT(fk_flare_set_load_preset(nullptr, "subtle"), 0);
    EXPECT_NE(std::string(fk_flare_set_error(nullptr)).find("expected a flare set"),
              std::string::npos);
    SetPtr set(fk_flare_set_create());
    fk_flare_set* s = set.get();
    const auto error = [s] { return std::string(fk_flare_set_error(s)); };
    EXPECT_LT(fk_flare_set_load_preset_json(s, "{\"elements\": [}", 15), 0);
    EXPECT_NE(error().find("fk_flare_set_load_preset_json: json"), std::string::npos) << error();
    const std::string bad = R"({"elements": [{"type": "ring", "size": -1}]})";
    EXPECT_LT(fk_flare_set_load_preset_json(s, bad.data(), bad.size()), 0);
    EXPECT_NE(error().find("size"), std::string::npos) << error();
    EXPECT_LT(fk_flare_set_load_preset(s, "no-such-preset"), 0);
    ASSERT_EQ(fk_flare_set_load_preset(s, "subtle"), 0);
    // Not prepared since the load: refused, nothing written.
    Scene scene = lampScene(4, 3, false, 320, 180);
    const std::vector<fk_light> lights = engineLights(scene, 0);
    fk_frame frame{};
    const DepthTarget none{};
    frame = frameFor(scene, none, {0, 0, 320, 180}, FK_DEPTH_ZERO_TO_ONE);
    frame.width = 320, frame.height = 180;
    float coverage[4] = {1, 1, 1, 1};
    fk_flare_instance out[64];
    std::memset(out, 0xab, sizeof out);
    EXPECT_LT(fk_flare_set_instances(s, &frame, lights.data(), coverage, 4, 0.08f, out, 64), 0);
    EXPECT_NE(error().find("fk_flare_set_prepare"), std::string::npos) << error();
    ASSERT_GT(fk_flare_set_prepare(s, 180), 0);
    frame.viewport[3] = 170;
    EXPECT_LT(fk_flare_set_instances(s, &frame, lights.data(), coverage, 4, 0.08f, out, 64), 0);
    EXPECT_NE(error().find("prepared height 180"), std::string::npos) << error();
    frame.viewport[3] = 180;
    coverage[2] = 1.5f;
    EXPECT_LT(fk_flare_set_instances(s, &frame, lights.data(), coverage, 4, 0.08f, out, 64), 0);
    EXPECT_NE(error().find("coverage[2]: expected 0..1"), std::string::npos) << error();
    coverage[2] = 1;
    EXPECT_LT(fk_flare_set_instances(s, &frame, lights.data(), coverage, 4, -1.f, out, 64), 0);
    EXPECT_NE(error().find("edge_fade"), std::string::npos) << error();
    EXPECT_LT(fk_flare_set_instances(s, &frame, lights.data(), coverage, 4, 0.08f, nullptr, 3), 0);
    std::vector<fk_light> wrong = lights;
    wrong[1].preset = 7;
    EXPECT_LT(fk_flare_set_instances(s, &frame, wrong.data(), coverage, 4, 0.08f, out, 64), 0);
    EXPECT_NE(error().find("lights[1].preset"), std::string::npos) << error();
    unsigned char untouched[sizeof out];
    std::memset(untouched, 0xab, sizeof untouched);
    EXPECT_EQ(std::memcmp(out, untouched, sizeof out), 0);
    // A short array gets what fits, and the count says how many there are.
    const int all = fk_flare_set_instances(s, &frame, lights.data(), coverage, 4, 0.08f, out, 2);
    EXPECT_GT(all, 2) << error();
    EXPECT_NE(std::memcmp(out, untouched, 2 * sizeof(fk_flare_instance)), 0);
    EXPECT_EQ(std::memcmp(out + 2, untouched, sizeof(fk_flare_instance)), 0);
    int w = 0, h = 0;
    EXPECT_LT(fk_flare_set_texture(s, 99, &w, &h, nullptr), 0);
    EXPECT_NE(error().find("slot"), std::string::npos);
    EXPECT_LT(fk_flare_set_prepare(s, 0), 0);
}

TEST(EngineInstances, TheExportedShadersAreValidSpirvHlslAndMsl) {
    TempDir dir;
    for (fk_shader_stage stage : {FK_SHADER_VERTEX, FK_SHADER_FRAGMENT}) {
        const char* name = stage == FK_SHADER_VERTEX ? "vert" : "frag";
        std::size_t size = 0;
        const auto* spirv =
            static_cast<const unsigned char*>(fk_flare_shader(FK_SHADER_SPIRV, stage, &size));
        ASSERT_NE(spirv, nullptr);
        ASSERT_EQ(size % 4, 0u);
        std::uint32_t magic = 0;
        std::memcpy(&magic, spirv, 4);
        EXPECT_EQ(magic, 0x07230203u);
        const std::string spv = dir.file(std::string(name) + ".spv");
        std::ofstream(spv, std::ios::binary)
            .write(reinterpret_cast<const char*>(spirv), std::streamsize(size));
        EXPECT_EQ(std::system(("spirv-val --target-env vulkan1.1 " + spv).c_str()), 0);
        // The HLSL compiles (glslang's HLSL front end), with the documented registers.
        const std::string hlsl = shaderText(FK_SHADER_HLSL, stage);
        const std::string hlslFile = dir.file(std::string(name) + ".hlsl");
        std::ofstream(hlslFile) << hlsl;
        EXPECT_EQ(std::system(("glslangValidator -V -D -e main -S " + std::string(name) + " " +
                               hlslFile + " -o " + dir.file("hlsl.spv") + " > /dev/null")
                                  .c_str()),
                  0)
            << hlsl;
        const std::string msl = shaderText(FK_SHADER_MSL, stage);
        EXPECT_NE(msl.find("#include <metal_stdlib>"), std::string::npos);
        if (stage == FK_SHADER_VERTEX) {
            EXPECT_NE(hlsl.find("register(t0)"), std::string::npos);
            EXPECT_NE(hlsl.find("cbuffer Frame : register(b1)"), std::string::npos);
            EXPECT_NE(msl.find("[[buffer(0)]]"), std::string::npos);
            EXPECT_NE(msl.find("constant Frame& frame [[buffer(1)]]"), std::string::npos);
            EXPECT_NE(msl.find("vertex main0_out main0("), std::string::npos);
        } else {
            EXPECT_NE(hlsl.find("Texture2D<float4> sprite : register(t2)"), std::string::npos);
            EXPECT_NE(hlsl.find("register(s2)"), std::string::npos);
            EXPECT_NE(msl.find("[[texture(0)]]"), std::string::npos);
            EXPECT_NE(msl.find("fragment main0_out main0("), std::string::npos);
        }
    }
    std::size_t size = 7;
    fk_shader_language unknown;  // what a C caller may store in the enum
    const int nine = 9;
    std::memcpy(&unknown, &nine, sizeof nine);
    EXPECT_EQ(fk_flare_shader(unknown, FK_SHADER_VERTEX, &size), nullptr);
    EXPECT_EQ(size, 0u);
}
