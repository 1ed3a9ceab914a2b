// SPDX-License-Identifier: Apache-2.0
// The flare's GPU half against its CPU twins: the sprite flare against renderFlare (equal
// where element centres sit on pixel centres, same energy elsewhere), the temporal filter
// against TemporalFilter, the tone map against tonemapAcesFitted, and a zero weight drawing
// nothing at all.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <epoxy/gl.h>
#include "GlTestContext.h"
#include "flarekit/Tonemap.h"
#include "flarekit/gl/GpuFlare.h"
#include "flarekit/gl/GpuVisibility.h"

#include "scene/CameraMath.h"

using namespace flarekit;

namespace {

RenderOptions noShadows() {
    RenderOptions o;
    o.shadows = false;
    return o;
}

//! A scene with no objects whose sun projects to pixel (px, py) (top-left origin).
Scene sceneWithSunAt(double px, double py) {
    Scene s;  // 640x360, default camera
    const CameraBasis b = cameraBasis(s.camera);
    const double tanY = std::tan(s.camera.fovYDeg * 3.14159265358979323846 / 360.0);
    const double tanX = tanY * s.width / s.height;
    const double nx = px / s.width * 2 - 1, ny = 1 - py / s.height * 2;
    s.sun.direction = normalize(b.forward + b.right * (nx * tanX) + b.up * (ny * tanY));
    return s;
}

//! A 1x1 RGBA32F texture the test owns (plain GL: the library's wrappers are internal).
class TestTexture {
  public:
    TestTexture() {
        glCreateTextures(GL_TEXTURE_2D, 1, &m_name),
            glTextureStorage2D(m_name, 1, GL_RGBA32F, 1, 1);
    }
    ~TestTexture() { glDeleteTextures(1, &m_name); }
    TestTexture(const TestTexture&) = delete;
    TestTexture& operator=(const TestTexture&) = delete;
    GLuint get() const { return m_name; }

  private:
    GLuint m_name = 0;
};

//! A 1x1 texture holding `values`: a stand-in for a method's or the filter's result.
std::unique_ptr<TestTexture> weightTexture(float r, float g = 0, float b = 0, float a = 0) {
    auto t = std::make_unique<TestTexture>();
    const float v[4] = {r, g, b, a};
    glTextureSubImage2D(t->get(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, v);
    return t;
}

//! The frame with the GL flare drawn over it (weight `weight`), and the CPU flare over the
//! same frame read back first.
struct FlarePair {
    Image gpu, cpu;
};
FlarePair drawBoth(const Preset& preset, const Scene& scene, float weight) {
    auto renderer = SceneRenderer::create(scene, noShadows());
    EXPECT_TRUE(renderer.ok()) << renderer.error().message;
    EXPECT_TRUE(renderer->draw(scene).ok());
    auto base = renderer->readColor();
    EXPECT_TRUE(base.ok());
    auto flare = GpuSpriteFlare::create(preset, scene.height);
    EXPECT_TRUE(flare.ok()) << flare.error().message;
    const auto w = weightTexture(weight);
    auto drawn = flare->draw(*renderer, scene, {w->get(), 0});
    EXPECT_TRUE(drawn.ok()) << drawn.error().message;
    auto gpu = renderer->readColor();
    EXPECT_TRUE(gpu.ok());
    FlarePair pair{std::move(*gpu), std::move(*base)};
    addSunFlare(pair.cpu, scene, preset, weight);
    return pair;
}

//! Pixels where the two differ by more than `relative` x max(1, |cpu|) in some channel.
std::size_t mismatches(const Image& gpu, const Image& cpu, float relative) {
    std::size_t bad = 0;
    for (std::size_t i = 0; i < cpu.pixelCount() * 4; i += 4) {
        for (std::size_t c = 0; c < 3; ++c) {
            const float a = gpu.data()[i + c], b = cpu.data()[i + c];
            if (std::fabs(a - b) > relative * std::max(1.f, std::fabs(b))) {
                if (std::getenv("FK_DEBUG") && bad < 20) {
                    std::printf("pixel %zu,%zu c%zu: gpu %g cpu %g\n", (i / 4) % cpu.width(),
                                (i / 4) / cpu.width(), c, a, b);
                }
                ++bad;
                break;
            }
        }
    }
    return bad;
}

double energy(const Image& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.pixelCount() * 4; i += 4)
        sum += image.data()[i] + image.data()[i + 1] + image.data()[i + 2];
    return sum;
}

//! Every element type and blend mode, at flare-vector positions that are whole pixels for a
//! light 240 px right and 120 px up of the centre.
Preset everyKind() {
    Preset p;
    p.name = "every-kind";
    const ElementType types[] = {ElementType::Glow, ElementType::Ring, ElementType::Streaks,
                                 ElementType::Rays, ElementType::Disc, ElementType::Polygon};
    const float ts[] = {1.f, 1.f, 1.f, 0.5f, -0.25f, -0.75f};
    const BlendMode blends[] = {BlendMode::Add, BlendMode::Screen, BlendMode::Add,
                                BlendMode::Add, BlendMode::Over,   BlendMode::Screen};
    for (int i = 0; i < 6; ++i) {
        ElementParams e;
        e.type = types[i];
        e.t = ts[i];
        e.size = 0.08f + 0.03f * float(i);
        e.color = {0.9f, 0.5f + 0.05f * float(i), 0.3f};
        e.innerColor = Rgb{1.f, 1.f, 1.f};
        // Screen is display-referred: kept below 1 here, since s + d - s d of two HDR values
        // near 2 cancels to a small number that half-float targets cannot resolve.
        e.intensity = blends[i] == BlendMode::Screen ? 0.12f : 0.6f;
        e.aspect = i == 2 ? 1.8f : 1.f;
        e.rotationDeg = 15.f * float(i);
        e.count = i == 3 ? 40 : 6;
        e.blend = blends[i];
        p.elements.push_back(e);
    }
    return p;
}

}  // namespace

TEST(GpuSpriteFlare, EqualsTheCpuFlareWhereElementsSitOnPixelCentres) {
    test::glContext();
    // Light at (560, 60): offset (240, -120) from the centre, so t x offset is whole pixels.
    const Scene scene = sceneWithSunAt(560, 60);
    const FlarePair pair = drawBoth(everyKind(), scene, 0.75f);
    // Half-float targets and textures: 11-bit mantissas, a few steps of 1/2048 after blending.
    EXPECT_EQ(mismatches(pair.gpu, pair.cpu, 4e-3f), 0u);
}

TEST(GpuSpriteFlare, ShippedPresetsMatchTheCpuFlare) {
    test::glContext();
    const Scene scene = sceneWithSunAt(560, 60);
    for (const std::string& name : shippedPresetNames()) {
        auto preset = loadPreset(name);
        ASSERT_TRUE(preset.ok()) << name;
        const FlarePair pair = drawBoth(*preset, scene, 1.f);
        // Shipped positions like t = -0.8333 land up to 0.01 px off a pixel centre: bilinear
        // filtering moves a thin streak's edge pixels by about that share.
        EXPECT_LT(mismatches(pair.gpu, pair.cpu, 2e-2f), pair.cpu.pixelCount() / 2000) << name;
        EXPECT_NEAR(energy(pair.gpu) / energy(pair.cpu), 1.0, 2e-3) << name;
    }
}

TEST(GpuSpriteFlare, SubPixelLightKeepsTheFlaresEnergy) {
    test::glContext();
    Scene scene = sceneWithSunAt(401.37, 97.81);
    // A dim disc (50) with a strong flare (weight 60, scale 4.6): half-float rounding of a disc
    // of thousands, and of a faint flare over the whole frame, would swamp the difference.
    scene.sun.intensity = 50.0;
    auto renderer = SceneRenderer::create(scene, noShadows());
    ASSERT_TRUE(renderer.ok());
    ASSERT_TRUE(renderer->draw(scene).ok());
    const double base = energy(*renderer->readColor());
    auto preset = loadPreset("tanczos-classic");
    ASSERT_TRUE(preset.ok());
    const FlarePair pair = drawBoth(*preset, scene, 60.f);
    // Bilinear sampling at a sub-pixel offset blurs thin streaks a little but keeps their light.
    EXPECT_NEAR((energy(pair.gpu) - base) / (energy(pair.cpu) - base), 1.0, 0.01);
}

TEST(GpuSpriteFlare, ZeroWeightDrawsNothingAndWeightScalesAdditiveElements) {
    test::glContext();
    const Scene scene = sceneWithSunAt(500, 100);
    auto preset = loadPreset("tanczos-classic");
    ASSERT_TRUE(preset.ok());
    const FlarePair none = drawBoth(*preset, scene, 0.f);
    EXPECT_EQ(mismatches(none.gpu, none.cpu, 0.f), 0u);  // bit-identical to the bare frame
    for (float w : {0.25f, 1.f}) {
        const FlarePair pair = drawBoth(everyKind(), scene, w);
        EXPECT_LT(mismatches(pair.gpu, pair.cpu, 2e-2f), pair.cpu.pixelCount() / 1000) << w;
    }
}

TEST(GpuTemporalFilter, FollowsTheCpuFilterFrameByFrame) {
    test::glContext();
    TemporalParams params;
    params.attackSeconds = 0.05, params.releaseSeconds = 0.2, params.adaptStrength = 0.9;
    auto gpu = GpuTemporalFilter::create(params);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message;
    TemporalFilter cpu(params);
    const auto raw = weightTexture(0);
    const double inputs[] = {0.3, 1.0,  1.0, 0.0, 0.0, 0.5, NAN, INFINITY,
                             1.7, -0.4, 0.8, 0.8, 0.1, 0.9, 1.0, 0.0};
    for (int i = 0; i < 16; ++i) {
        const float v = float(inputs[i]);
        glTextureSubImage2D(raw->get(), 0, 0, 0, 1, 1, GL_RED, GL_FLOAT, &v);
        // The sun walks from the centre off the right edge and ends behind the camera.
        const Point sun{320.f + 25.f * float(i), 180.f - 4.f * float(i)};
        const bool inFront = i < 14;
        const double dt = i == 0 ? 0.0 : 1.0 / (20 + 5 * (i % 3));
        ASSERT_TRUE(gpu->update({raw->get(), 0}, sun, inFront, 640, 360, dt).ok());
        const TemporalState want = cpu.update(inputs[i], sun, inFront, 640, 360, dt);
        auto got = gpu->readState();
        ASSERT_TRUE(got.ok());
        EXPECT_NEAR(got->coverage, want.coverage, 2e-6) << "frame " << i;
        EXPECT_NEAR(got->edgeFade, want.edgeFade, 2e-6) << "frame " << i;
        EXPECT_NEAR(got->exposure, want.exposure, 2e-6) << "frame " << i;
        EXPECT_NEAR(got->flareWeight, want.flareWeight, 2e-6) << "frame " << i;
        const double target = std::isfinite(inputs[i]) ? std::clamp(inputs[i], 0.0, 1.0) : 0.0;
        EXPECT_DOUBLE_EQ(*gpu->readConsumedCoverage(), double(float(target))) << "frame " << i;
    }
}

TEST(GpuTonemap, EqualsTheCpuToneMapWithTheExposureFromATexture) {
    test::glContext();
    const Scene scene = sceneWithSunAt(300, 120);  // the sun disc: 50 x its colour
    auto renderer = SceneRenderer::create(scene, noShadows());
    ASSERT_TRUE(renderer.ok());
    ASSERT_TRUE(renderer->draw(scene).ok());
    auto tonemap = GpuTonemap::create(scene.width, scene.height);
    ASSERT_TRUE(tonemap.ok());
    const auto exposure = weightTexture(0, 0, 0.37f, 0);
    for (float e : {1.f, 0.37f}) {
        ASSERT_TRUE(
            tonemap->apply(*renderer, e == 1.f ? GpuChannel{} : GpuChannel{exposure->get(), 2})
                .ok());
        auto gpu = tonemap->read();
        ASSERT_TRUE(gpu.ok());
        Image cpu = *renderer->readColor();
        tonemapAcesFitted(cpu, e);
        EXPECT_EQ(mismatches(*gpu, cpu, 1e-3f), 0u) << e;  // the display target is half float
    }
    Scene small;
    small.width = 160, small.height = 90;
    EXPECT_FALSE(tonemap->apply(*SceneRenderer::create(small)).ok());  // size mismatch
}

TEST(GpuSpriteFlare, ConditionalRenderOnTheQuerySkipsTheFlareOfAHiddenSun) {
    test::glContext();
    auto preset = loadPreset("tanczos-classic");
    ASSERT_TRUE(preset.ok());
    for (const bool hidden : {true, false}) {
        Scene scene = sceneWithSunAt(400, 120);
        // A sphere on the sun's ray 30 m away, 3 m across: covers the 1.5-degree disc whole.
        if (hidden)
            scene.spheres.push_back({scene.camera.position + scene.sun.direction * 30.0, 1.5});
        auto renderer = SceneRenderer::create(scene, noShadows());
        ASSERT_TRUE(renderer.ok());
        auto query = createGpuVisibility("query", scene);
        ASSERT_TRUE(query.ok());
        ASSERT_TRUE(renderer->draw(scene).ok());
        ASSERT_TRUE((*query)->measure(scene, *renderer).ok());
        ASSERT_NE((*query)->conditionalRenderQuery(), 0u);
        glFinish();  // the test wants the query's answer, not GL_QUERY_NO_WAIT's licence to guess
        const double base = energy(*renderer->readColor());
        auto flare = GpuSpriteFlare::create(*preset, scene.height);
        ASSERT_TRUE(flare.ok());
        // A weight of 1 regardless: only the conditional render can keep the flare away.
        const auto one = weightTexture(1.f);
        ASSERT_TRUE(
            flare->draw(*renderer, scene, {one->get(), 0}, (*query)->conditionalRenderQuery())
                .ok());
        const double after = energy(*renderer->readColor());
        if (hidden) {
            EXPECT_EQ(after, base);
        } else {
            // The flare adds light across the frame: 0.05 per pixel on average at least (the
            // sun disc's own thousands make a relative test meaningless).
            EXPECT_GT(after - base, 0.05 * double(scene.width) * double(scene.height));
        }
    }
}
