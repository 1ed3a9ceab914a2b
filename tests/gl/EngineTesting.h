// SPDX-License-Identifier: Apache-2.0
// Shared by the engine API's GL tests (Engine*Test.cpp): an engine owner, the
// ray-cast truth at 4,096 rays a light, the worst error against it, a temporary preset file,
// the wall scene and the application GL state the engine must leave alone.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "DepthPass.h"
#include "GlTestContext.h"
#include "flarekit/Visibility.h"
#include "flarekit/flarekit.h"

namespace flarekit::test {

// The API's accuracy bound against the ray caster (4x MSAA depth).
constexpr double kTolerance = 0.02;

struct EngineDeleter {
    void operator()(fk_engine* e) const { fk_engine_destroy(e); }
};
using EnginePtr = std::unique_ptr<fk_engine, EngineDeleter>;

inline EnginePtr makeEngine(int maxLights) {
    glContext();
    EnginePtr e(fk_engine_create(maxLights));
    EXPECT_TRUE(e) << fk_error(nullptr);
    return e;
}

inline std::vector<float> readCoverage(fk_engine* e, int count) {
    std::vector<float> c(std::size_t(count), -1.f);
    EXPECT_EQ(fk_engine_read_coverage(e, c.data(), count), count) << fk_error(e);
    return c;
}

inline VisibilityResult truth(const Scene& s) {
    RaycastOptions o;
    o.samplesPerSide = 64;  // 4,096 rays a light: error near 0.003, well inside 0.02
    auto r = raycastVisibility(s, o);
    EXPECT_TRUE(r.ok());
    return *r;
}

//! Worst |engine - raycast| over the lights, and how many lights were partly hidden.
inline double worstError(const std::vector<float>& engine, const VisibilityResult& rays,
                         int* partial) {
    double worst = 0;
    *partial = 0;
    for (std::size_t i = 0; i < engine.size(); ++i) {
        worst = std::max(worst, std::abs(double(engine[i]) - rays.lights[i].coverage));
        if (rays.lights[i].coverage > 0.02 && rays.lights[i].coverage < 0.98) ++*partial;
    }
    return worst;
}

//! A preset file holding one edge streak, removed afterwards.
struct TempPreset {
    std::string path = std::filesystem::temp_directory_path() /
                       ("flarekit-edge-" + std::to_string(::getpid()) + ".json");
    TempPreset() {
        std::ofstream(path) << R"({"name": "edge", "elements": [{"type": "edge-streak", "size": )"
                               R"(0.25, "aspect": 8, "reach": 0.3, "intensity": 0.8}]})";
    }
    ~TempPreset() { std::filesystem::remove(path); }
};

inline Scene wallScene() {
    Scene s;
    s.width = 320, s.height = 180;
    s.camera.position = {0, 0, 0};
    s.camera.lookAt = {0, 0, -1};
    s.camera.farPlane = 500;
    s.sun.intensity = 0;
    s.boxes.push_back({{-4, -4, -21}, {4, 4, -20}});
    SceneLight front, behind, ahead, aside;
    front.type = behind.type = LightType::Point;
    front.position = {0.5, 0.5, -10}, front.radius = 0.2;
    behind.position = {0.5, 0.5, -30}, behind.radius = 0.2;
    ahead.direction = {0, 0, -1};                       // straight into the wall
    aside.direction = normalize(Vec3{0.35, 0.15, -1});  // in frame, past the wall's edge
    s.lights = {front, behind, ahead, aside};
    return s;
}

//! Every piece of state GlStateGuard promises to keep, read back.
struct AppState {
    GLint program, vao, drawFb, readFb, viewport[4], active, image, ssbo5, ssbo6, ssbo7,
        ssboGeneric;
    GLint units[4][3];  // 2D, 2D multisample, sampler on units 12-15
    GLboolean blend0, blend1, depthTest, depthMask, scissor, cull, stencil, mask0[4], mask1[4];
    GLint src0, dst0, eq0, src1, polygon[2];
    bool operator==(const AppState&) const = default;
};

inline AppState readState() {
    AppState s{};
    glGetIntegerv(GL_CURRENT_PROGRAM, &s.program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &s.vao);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.drawFb);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &s.readFb);
    glGetIntegerv(GL_VIEWPORT, s.viewport);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &s.active);
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 7, &s.image);
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 5, &s.ssbo5);
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 6, &s.ssbo6);
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 7, &s.ssbo7);
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &s.ssboGeneric);
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (int u = 0; u < 4; ++u) {
        glActiveTexture(GLenum(GL_TEXTURE12 + u));
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &s.units[u][0]);
        glGetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &s.units[u][1]);
        glGetIntegerv(GL_SAMPLER_BINDING, &s.units[u][2]);
    }
    glActiveTexture(GLenum(active));
    s.blend0 = glIsEnabledi(GL_BLEND, 0);
    s.blend1 = glIsEnabledi(GL_BLEND, 1);
    glGetIntegeri_v(GL_BLEND_SRC_RGB, 0, &s.src0);
    glGetIntegeri_v(GL_BLEND_DST_RGB, 0, &s.dst0);
    glGetIntegeri_v(GL_BLEND_EQUATION_RGB, 0, &s.eq0);
    glGetIntegeri_v(GL_BLEND_SRC_RGB, 1, &s.src1);
    glGetBooleani_v(GL_COLOR_WRITEMASK, 0, s.mask0);
    glGetBooleani_v(GL_COLOR_WRITEMASK, 1, s.mask1);
    s.depthTest = glIsEnabled(GL_DEPTH_TEST);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &s.depthMask);
    s.scissor = glIsEnabled(GL_SCISSOR_TEST);
    s.cull = glIsEnabled(GL_CULL_FACE);
    s.stencil = glIsEnabled(GL_STENCIL_TEST);
    glGetIntegerv(GL_POLYGON_MODE, s.polygon);
    return s;
}

}  // namespace flarekit::test
