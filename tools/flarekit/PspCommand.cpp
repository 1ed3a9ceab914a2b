// SPDX-License-Identifier: Apache-2.0
// flarekit psp: the Burnout Dominator lens flare (and Ridge Racer's simpler one) run as GE
// display lists on the emulated PSP Graphics Engine, correct or as a naive emulator runs it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "Common.h"
#include "JsonLine.h"
#include "ParamOptions.h"
#include "Progress.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Psp.h"

namespace flarekit::cli {

namespace {
struct PspArgs {
    std::string occluders, sun, out, dumpDir, traceFile;
    bool naive = false, json = false;
};

std::string jsonLine(psp::PspTrick trick, bool naive, const psp::PspFrameResult& r) {
    const bool burnout = trick == psp::PspTrick::Burnout;
    JsonLine j;
    j.text("trick", burnout ? "burnout" : "ridge-racer").text("mode", naive ? "naive" : "correct");
    j.boolean("sun_in_frame", r.sunInFrame).integer("coverage_byte", r.coverageByte);
    burnout ? j.integer("clut_alpha", r.clutAlpha) : j.null("clut_alpha");
    j.integer("visible_pixels", r.visiblePixels).integer("mask_pixels", r.maskPixels);
    r.sunInFrame ? j.boolean("region_restored", r.regionRestored) : j.null("region_restored");
    return j.str();
}

int runPsp(psp::PspTrick trick, const PspArgs& a) {
    const auto sun = parsePoint(a.sun);
    if (!sun)
        return report(invalidInput("--sun: expected X,Y in screen pixels, e.g. 240,100, got '" +
                                   a.sun + "'"));
    psp::PspFrameJobOptions o;
    o.occluders = a.occluders;
    // Clamped before the conversion to int; the library rejects anything past +-8192.
    auto pixel = [](float v) { return int(std::floor(std::clamp(double(v), -1e6, 1e6))); };
    o.sunX = pixel(sun->x), o.sunY = pixel(sun->y);
    o.naive = a.naive;
    o.output = a.out, o.dumpDir = a.dumpDir, o.traceFile = a.traceFile;
    o.encode = encodeSettings();
    auto r = psp::runPspFrameJob(trick, o);
    if (!r) return report(r.error());
    if (a.json) {
        std::printf("%s\n", jsonLine(trick, a.naive, *r).c_str());
    } else if (!r->sunInFrame) {
        std::printf("psp: the sun (%d, %d) is outside the 480x272 screen: no mask, no flare\n",
                    o.sunX, o.sunY);
    } else {
        std::printf("psp %s (%s): %d of %d mask pixels visible, coverage byte %d",
                    trick == psp::PspTrick::Burnout ? "burnout" : "ridge-racer",
                    a.naive ? "naive" : "correct", r->visiblePixels, r->maskPixels,
                    r->coverageByte);
        if (trick == psp::PspTrick::Burnout) std::printf(", flare CLUT alpha %d", r->clutAlpha);
        std::printf("\n");
    }
    return kExitOk;
}

int runPspDemoCommand(const psp::PspDemoOptions& a) {
    Progress progress("psp demo", a.frames);
    if (Status s = psp::runPspDemo(a, [&](int done, int) { progress.update(done); }); !s)
        return report(s.error());
    progress.finish();
    const std::string dir = std::filesystem::path(a.outDir).string() + "/";
    std::printf("psp demo: %d frames (correct left, naive right) in %s, log %scoverage.csv\n",
                a.frames, dir.c_str(), dir.c_str());
    return kExitOk;
}

void addTrick(CLI::App& psp, const char* name, psp::PspTrick trick, const char* about,
              int& exitCode) {
    auto args = std::make_shared<PspArgs>();
    CLI::App* cmd = psp.add_subcommand(name, about);
    cmd->add_option("--occluders", args->occluders,
                    "480x272 mask image, non-zero = occluder in front of the sun")
        ->required();
    cmd->add_option("--sun", args->sun,
                    "the sun's centre X,Y in screen pixels (outside the screen: no flare)")
        ->required();
    cmd->add_option("-o,--output", args->out, "the final frame (PNG)")->required();
    cmd->add_flag("--naive", args->naive,
                  "run as a naive emulator: render targets kept apart from CLUT memory");
    cmd->add_option("--dump", args->dumpDir, "write every step as a PNG into this directory");
    cmd->add_option("--trace", args->traceFile,
                    "write one line per executed GE command to this file");
    cmd->add_flag("--json", args->json,
                  "print one JSON object: coverage_byte, clut_alpha, visible_pixels, ...");
    cmd->callback([args, trick, &exitCode] { exitCode = runPsp(trick, *args); });
}
}  // namespace

void addPspCommand(CLI::App& app, int& exitCode) {
    CLI::App* psp = app.add_subcommand(
        "psp", "the Burnout Dominator lens flare on an emulated PSP GE (bit-exact)");
    psp->require_subcommand(1);
    addTrick(*psp, "burnout", psp::PspTrick::Burnout,
             "Burnout Dominator: 14x14 mask, bilinear chain, coverage into the flare CLUT's alpha",
             exitCode);
    addTrick(
        *psp, "ridge-racer", psp::PspTrick::RidgeRacer,
        "Ridge Racer: 16x16 mask summed by blending, coverage as a texture on gouraud hexagons",
        exitCode);
    auto demo = std::make_shared<psp::PspDemoOptions>();
    CLI::App* cmd = psp->add_subcommand(
        "demo", "the demo drive through the emulator, correct and naive side by side");
    cmd->add_option("-o,--output", demo->outDir, "output directory (frames + coverage.csv)")
        ->required();
    addParamOptions<psp::PspDemoOptions>(cmd, psp::kPspDemoParams, *demo);
    cmd->callback([demo, &exitCode] {
        demo->encode = encodeSettings();  // the global flags, parsed by now
        exitCode = runPspDemoCommand(*demo);
    });
}

}  // namespace flarekit::cli
