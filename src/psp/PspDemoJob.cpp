// SPDX-License-Identifier: Apache-2.0
// `flarekit psp demo` as a library job: every frame of the demo drive run twice on the emulated
// GE (correct and naive), written side by side, with the coverage log beside them.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "core/SafeWrite.h"
#include "flarekit/ImageIO.h"
#include "flarekit/ParamText.h"
#include "flarekit/Psp.h"

namespace flarekit::psp {

namespace {
//! Side by side: the correct frame left, the naive one right.
Image8 sideBySide(const Image8& left, const Image8& right) {
    Image8 out{
        left.width + right.width, left.height, 3,
        std::vector<std::uint8_t>(std::size_t((left.width + right.width) * left.height * 3))};
    for (int y = 0; y < left.height; ++y) {
        std::copy_n(&left.pixels[std::size_t(y * left.width * 3)], left.width * 3,
                    &out.pixels[std::size_t(y * out.width * 3)]);
        std::copy_n(&right.pixels[std::size_t(y * right.width * 3)], right.width * 3,
                    &out.pixels[std::size_t((y * out.width + left.width) * 3)]);
    }
    return out;
}
}  // namespace

Status runPspDemo(const PspDemoOptions& a, const std::function<void(int, int)>& progress) {
    if (Status s = validateParams<PspDemoOptions>(a, kPspDemoParams, "--"); !s) return s;
    if (Status s = makeOutputDirectory(a.outDir); !s) return s;
    const std::string dir = std::filesystem::path(a.outDir).string() + "/";
    std::string csv =
        "frame,t,sun_x,sun_y,sun_in_frame,visible_pixels,coverage_byte,clut_alpha_correct,clut_"
        "alpha_naive\n";
    for (int i = 0; i < a.frames; ++i) {
        const double t = a.frames > 1 ? double(i) / (a.frames - 1) : 0.0;
        auto in = pspDemoInput(t);
        if (!in) return in.error();
        auto correct = runPspFrame(PspTrick::Burnout, *in);
        if (!correct) return correct.error();
        in->naive = true;
        auto naive = runPspFrame(PspTrick::Burnout, *in);
        if (!naive) return naive.error();
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", i + 1);
        if (Status s = writeImage8(dir + name, sideBySide(correct->frame, naive->frame), a.encode);
            !s)
            return s;
        char row[160];
        std::snprintf(row, sizeof row, "%d,%.4f,%d,%d,%d,%d,%d,%d,%d\n", i + 1, t, in->sunX,
                      in->sunY, correct->sunInFrame ? 1 : 0, correct->visiblePixels,
                      correct->coverageByte, correct->clutAlpha, naive->clutAlpha);
        csv += row;
        if (progress) progress(i + 1, a.frames);
    }
    return writeFileSafely(dir + "coverage.csv", csv);
}

}  // namespace flarekit::psp
