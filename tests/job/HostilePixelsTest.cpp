// SPDX-License-Identifier: Apache-2.0
// Plates with samples no camera makes but every pipeline meets: a resize's negative ringing
// beside an HDR sun, NaN, infinities, denormals and the largest half (65504). Light is never
// negative, so none of them may darken or blow up the flare: every job's output is finite, and
// a plate whose only fault is negative ringing gets the flare of the same plate without it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "TempDir.h"
#include "flarekit/ImageIO.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/job/ApplyJob.h"
#include "flarekit/job/LensJob.h"
#include "flarekit/job/PostFxJob.h"

namespace flarekit::test {
namespace {

constexpr int kW = 128, kH = 80;
constexpr float kSunX = 40.5f, kSunY = 30.5f;

//! A 0.2 plate with a sun of 50,000 (radius 3 px).
Image cleanPlate() {
    Image image(kW, kH);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const float d = std::hypot(float(x) + 0.5f - kSunX, float(y) + 0.5f - kSunY);
            const float v = d < 3.f ? 50000.f : 0.2f;
            image.at(x, y) = {v, v, v, 1.f};
        }
    return image;
}

//! The clean plate after a sinc-type resize: rings of -3,600 around the sun (as a Lanczos filter
//! leaves beside a 50,000 disc), one pixel at -10,000 far from it.
Image ringingPlate() {
    Image image = cleanPlate();
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const float d = std::hypot(float(x) + 0.5f - kSunX, float(y) + 0.5f - kSunY);
            if (d >= 3.f && d < 4.5f) image.at(x, y) = {-3600.f, -3600.f, -3600.f, 1.f};
        }
    image.at(100, 60) = {-10000.f, -10000.f, -10000.f, 1.f};
    return image;
}

//! The ringing plate with every other hostile sample somewhere in it.
Image hostilePlate() {
    Image image = ringingPlate();
    const float inf = std::numeric_limits<float>::infinity();
    image.at(5, 5) = {std::nanf(""), 0.2f, 0.2f, 1.f};
    image.at(6, 70) = {inf, inf, inf, 1.f};
    image.at(7, 70) = {-inf, 0.2f, 0.2f, 1.f};
    image.at(120, 10) = {65504.f, 65504.f, 65504.f, 1.f};
    image.at(121, 10) = {1e-42f, 1e-40f, -1e-41f, 1.f};  // denormals
    image.at(90, 40) = {-1000.f, 2.f, 2.f, 1.f};         // one channel negative
    return image;
}

std::string writePlate(const TempDir& dir, const std::string& name, const Image& image) {
    WriteOptions f32;
    f32.format = SampleFormat::Float;
    EXPECT_TRUE(writeImage(dir.file(name), image, f32));
    return dir.file(name);
}

Image readBack(const std::string& path) {
    auto loaded = readImage(path);
    EXPECT_TRUE(loaded) << (loaded ? "" : loaded.error().message);
    return loaded ? loaded->image : Image();
}

void expectFinite(const Image& image, const std::string& what) {
    ASSERT_FALSE(image.empty()) << what;
    std::size_t bad = 0;
    for (std::size_t i = 0; i < image.pixelCount() * 4; ++i) bad += !std::isfinite(image.data()[i]);
    EXPECT_EQ(bad, 0u) << what << ": non-finite output samples";
}

//! The flare the output adds, summed over the frame away from the sun and the faults (where the
//! two plates are the same).
double flareAwayFromFaults(const Image& out, const Image& plate) {
    double sum = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (std::hypot(float(x) + 0.5f - kSunX, float(y) + 0.5f - kSunY) < 6.f) continue;
            if (std::abs(x - 100) < 3 && std::abs(y - 60) < 3) continue;
            sum += double(out.at(x, y).g) - double(plate.at(x, y).g);
        }
    return sum;
}

TEST(HostilePixels, PostFxOnARingingPlateGivesTheCleanPlatesFlareOnEveryPreset) {
    TempDir dir;
    const Image clean = cleanPlate(), ringing = ringingPlate();
    const std::string cleanIn = writePlate(dir, "clean.exr", clean),
                      ringingIn = writePlate(dir, "ringing.exr", ringing);
    for (const std::string& preset : shippedPostFxPresetNames()) {
        SCOPED_TRACE(preset);
        PostFxJobOptions o;
        o.preset = preset;
        o.tonemap = ToneOperator::None;
        o.input = cleanIn, o.output = dir.file("clean-" + preset + ".exr");
        ASSERT_TRUE(runPostFxJob(o));
        o.input = ringingIn, o.output = dir.file("ringing-" + preset + ".exr");
        ASSERT_TRUE(runPostFxJob(o));
        const Image a = readBack(dir.file("clean-" + preset + ".exr")),
                    b = readBack(dir.file("ringing-" + preset + ".exr"));
        expectFinite(b, preset);
        const double want = flareAwayFromFaults(a, clean), got = flareAwayFromFaults(b, ringing);
        ASSERT_GT(want, 0);
        // The rings take the sun's rim (radius 3 to 4.5) out of the metering and the light: the
        // flare may differ by what that rim carried, never be black or thousands of times over.
        EXPECT_NEAR(got / want, 1.0, 0.05) << "flare " << got << " against " << want;
        // The plate passes through unchanged: its ringing is still there under the flare.
        EXPECT_LT(b.at(100, 60).g, -9000.f);
    }
}

TEST(HostilePixels, EveryJobOnEveryHostileSampleWritesAFiniteFlare) {
    TempDir dir;
    const std::string in = writePlate(dir, "hostile.exr", hostilePlate());
    for (const std::string& preset : shippedPostFxPresetNames()) {
        PostFxJobOptions o;
        o.preset = preset, o.input = in, o.output = dir.file("postfx-" + preset + ".exr");
        ASSERT_TRUE(runPostFxJob(o)) << preset;
        expectFinite(readBack(o.output), "postfx " + preset);
    }
    ApplyOptions apply;
    apply.input = in, apply.output = dir.file("apply.exr");
    ASSERT_TRUE(runApplyJob(apply));
    const Image applied = readBack(apply.output);
    expectFinite(applied, "apply");
    LensJobOptions lens;
    lens.lens = "angenieux-double-gauss";
    lens.input = in, lens.output = dir.file("lens.exr");
    lens.render.gridSide = 24;
    ASSERT_TRUE(runLensJob(lens));
    const Image rendered = readBack(lens.output);
    expectFinite(rendered, "lens render");
    // Both drew a flare of the sun (not nothing, not a frame pulled under by the rings): the
    // sky far from everything is brighter than the plate's 0.2, and not by thousands.
    for (const Image* out : {&applied, &rendered}) {
        double far = 0;
        for (int y = 50; y < 80; ++y) far += out->at(60, y).g;
        EXPECT_GE(far / 30, 0.2);
        EXPECT_LT(far / 30, 100);
    }
}

// --exposure is not silently dropped on a float output: with no display curve it scales the
// linear result (plate and flare alike), exactly.
TEST(PostFxExposure, AppliesToALinearExrOutput) {
    TempDir dir;
    const std::string in = writePlate(dir, "clean.exr", cleanPlate());
    PostFxJobOptions o;
    o.input = in;
    o.tonemap = ToneOperator::None;
    o.output = dir.file("one.exr");
    ASSERT_TRUE(runPostFxJob(o));
    o.exposure = 2.f;
    o.output = dir.file("two.exr");
    ASSERT_TRUE(runPostFxJob(o));
    const Image one = readBack(dir.file("one.exr")), two = readBack(dir.file("two.exr"));
    for (std::size_t i = 0; i < one.pixelCount() * 4; ++i)
        ASSERT_FLOAT_EQ(two.data()[i], i % 4 == 3 ? one.data()[i] : 2.f * one.data()[i]) << i;
}

}  // namespace
}  // namespace flarekit::test
