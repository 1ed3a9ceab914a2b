// SPDX-License-Identifier: Apache-2.0
// The Burnout Dominator lens flare run on an emulated PSP Graphics Engine (
// burnout-dominator-psp-lens-flare.md): the game's frame as a GE display list (scene, 14x14
// visibility mask, bilinear chain to one coverage byte, render into the flare texture's CLUT
// through a 565 alias with a write mask and a striped depth buffer, flare draw), executed by a
// software GE whose memory is memory. `naive` runs the same list on an emulator that keeps
// render targets apart from the memory CLUTs load from, which leaves the flare at full
// brightness behind everything. The Ridge Racer variant accumulates the coverage and uses it
// as a 1x1 texture modulating gouraud hexagons.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Param.h"
#include "flarekit/Result.h"
#include "flarekit/Scene.h"

namespace flarekit::psp {

constexpr int kScreenWidth = 480, kScreenHeight = 272;  //!< the PSP's display

enum class PspTrick {
    Burnout,    //!< 14x14 mask, bilinear chain, CLUT alpha through a 565 alias
    RidgeRacer  //!< 16x16 mask summed by additive blending, coverage as a texture on hexagons
};

struct PspFrameInput {
    //! kScreenWidth x kScreenHeight, row-major, non-zero = an occluder in front of the sun.
    std::vector<std::uint8_t> occluders;
    int sunX = 240, sunY = 100;  //!< the sun's centre in screen pixels
    bool naive = false;          //!< the naive emulator's memory model
    bool keepSteps = false;      //!< fill PspFrameResult::steps (the --dump images)
    bool trace = false;          //!< fill PspFrameResult::trace (one line per GE command)
};

struct PspStep {
    std::string name;  //!< file stem, e.g. "02-mask"
    Image8 image;      //!< RGB
};

struct PspFrameResult {
    Image8 frame;             //!< the displayed 480x272 RGB frame
    bool sunInFrame = false;  //!< false: no mask, no flare (documented behaviour)
    int coverageByte = 0;     //!< Burnout: the chain's last value; Ridge Racer: the accumulated sum
    int clutAlpha = 0;  //!< Burnout: the alpha of the flare CLUT the GE loaded for the flare draw
    int visiblePixels = 0;        //!< white pixels of the mask (what the coverage estimates)
    int maskPixels = 0;           //!< 196 (Burnout) or 256 (Ridge Racer)
    bool regionRestored = false;  //!< the backed-up region is bit-identical after the restore
    //! The flare CLUT as the GE's CLUT load reads it, before and after the CLUT render (8888).
    std::array<std::uint32_t, 256> clutBefore{}, clutAfter{};
    std::vector<PspStep> steps;
    std::vector<std::string> trace;
};

Result<PspFrameResult> runPspFrame(PspTrick trick, const PspFrameInput& input);

//! Frame `t` (0 = start, 1 = end) of the demo drive (flarekit/Demo.h) as emulator input: the
//! occluders ray-cast from the demo world at 480x272, the sun projected by its camera.
Result<PspFrameInput> pspDemoInput(double t);
//! The same for any scene whose image is 480x272: a pixel is an occluder when its camera ray
//! hits an object (only sky lies behind the sun); the sun where its direction projects.
Result<PspFrameInput> pspInputFromScene(const Scene& scene);

//! A 480x272 mask image (any channels; non-zero in the first channel = occluder) as occluders.
Result<std::vector<std::uint8_t>> occludersFromMask(const Image8& mask, const std::string& name);

//! `flarekit psp burnout|ridge-racer`: one frame of a trick from files, its outputs written.
struct PspFrameJobOptions {
    std::string occluders;   //!< 480x272 mask image (occludersFromMask)
    int sunX = 0, sunY = 0;  //!< the sun's centre in screen pixels (outside: no mask, no flare)
    bool naive = false;      //!< PspFrameInput::naive
    std::string output;      //!< the final frame (PNG)
    std::string dumpDir;     //!< every step as NAME.png here, made when missing (empty: none)
    std::string traceFile;   //!< one line per executed GE command (empty: none)
    EncodeSettings encode;   //!< of the images written
};
//! Reads the mask, runs the frame (runPspFrame) and writes the frame, the steps and the trace.
Result<PspFrameResult> runPspFrameJob(PspTrick trick, const PspFrameJobOptions& options);

//! `flarekit psp demo`: the demo drive through the emulator.
struct PspDemoOptions {
    std::string outDir;  //!< made when missing
    int frames = 48;
    EncodeSettings encode;  //!< of the frames written
};
//! 48 frames show the drive's sun blinking; 2000 bounds the run (each frame is two full GE frames).
inline constexpr Param<PspDemoOptions> kPspDemoParams[] = {
    param<&PspDemoOptions::frames>("frames", 1, 2000, "", "frames over the drive"),
};

//! Each frame correct (left) and naive (right) side by side as outDir/frame_NNNN.png, and
//! outDir/coverage.csv (frame, t, sun_x, sun_y, sun_in_frame, visible_pixels, coverage_byte,
//! clut_alpha_correct, clut_alpha_naive). `progress(done, total)` after each frame.
Status runPspDemo(const PspDemoOptions& options,
                  const std::function<void(int done, int total)>& progress = {});

}  // namespace flarekit::psp
