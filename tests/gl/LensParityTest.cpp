// SPDX-License-Identifier: Apache-2.0
// CPU vs OpenGL ghost rasterisers of `lens render`: the same traced meshes, the same masks and
// weights (src/lens/LensRender.cpp against src/lens/shaders/lens_ghost.frag). The ghost layers
// agree within 1e-3 relative (a floor of 1e-3 of the layer's peak for values near zero) at
// every value for every shipped lens. Runs on Mesa llvmpipe in CI; never skipped.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "GlTestContext.h"
#include "flarekit/gl/GpuLens.h"

namespace flarekit {
namespace {

constexpr double kRelative = 1e-3;

struct Diff {
    double worst = 0, peak = 0;
    int x = 0, y = 0;
    std::size_t over = 0;
};

Diff compare(const Image& cpu, const Image& gpu) {
    Diff d;
    for (std::size_t i = 0; i < cpu.pixelCount() * 4; ++i)
        if (i % 4 != 3) d.peak = std::max(d.peak, double(cpu.data()[i]));
    const double floor = 1e-3 * d.peak;
    for (int y = 0; y < cpu.height(); ++y) {
        for (int x = 0; x < cpu.width(); ++x) {
            for (int c = 0; c < 3; ++c) {
                const double a = cpu.row(y)[4 * x + c], b = gpu.row(y)[4 * x + c];
                const double rel = std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), floor});
                if (rel > kRelative) ++d.over;
                if (rel > d.worst) d.worst = rel, d.x = x, d.y = y;
            }
        }
    }
    return d;
}

}  // namespace

TEST(LensParity, EveryLensCpuGhostsMatchGl) {
    test::glContext();
    for (const std::string& name : lensNames()) {
        auto lens = loadLens(name);
        ASSERT_TRUE(lens.ok()) << name;
        LensRenderOptions o;
        o.ghosts = 24, o.starburst = 0, o.glare = 0;
        std::vector<LensLight> lights(2);
        lights[0].x = 250.3, lights[0].y = 90.7, lights[0].energy = {1e6, 1e6, 1e6};
        lights[1].x = 101.1, lights[1].y = 140.2, lights[1].energy = {2e5, 1e5, 5e4};
        auto cpu = renderLensFlare(*lens, 320, 180, lights, o);
        auto gpu = renderLensFlareGl(*lens, 320, 180, lights, o);
        ASSERT_TRUE(cpu.ok() && gpu.ok()) << name << ": " << (gpu.ok() ? "" : gpu.error().message);
        const Diff d = compare(cpu->ghosts, gpu->ghosts);
        std::printf("lens parity %-24s worst %.2e at %d,%d, %zu values over 1e-3, peak %.3g\n",
                    name.c_str(), d.worst, d.x, d.y, d.over, d.peak);
        // Both rasterisers cover the same pixel centres (vertices on the 1/256 grid, clipped to
        // the image by the shared code, one tie rule), weigh them by edge functions in double
        // and evaluate the masks in double on the CPU, float on the GPU. On llvmpipe every
        // lens agrees to 6e-5 at every value.
        EXPECT_EQ(d.over, 0u) << name;
        EXPECT_LT(d.worst, kRelative) << name;
        EXPECT_GT(d.peak, 0.0) << name;
    }
}

}  // namespace flarekit
