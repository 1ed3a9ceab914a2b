// SPDX-License-Identifier: Apache-2.0
// flarekit blend: Tanczos 1999's 8-bit blend formulas on whole images, bit-exact.
#include "Common.h"
#include "flarekit/Blend.h"
#include "flarekit/ImageIO.h"

namespace flarekit::cli {

namespace {
struct BlendArgs {
    std::string mode, src, dst, out;
};

int runBlend(const BlendArgs& a) {
    return runImage8Job(a.out, [&]() -> Result<Image8> {
        const Blend8Mode mode = *parseBlend8Mode(a.mode);  // CLI11 checked membership
        auto src = readImage8Quietly(a.src);
        if (!src) return src.error();
        auto dst = readImage8Quietly(a.dst);
        if (!dst) return dst.error();
        auto blended = blendImages8(mode, *src, *dst);
        if (!blended)
            return Error{blended.error().code,
                         a.src + " onto " + a.dst + ": " + blended.error().message};
        return blended;
    });
}
}  // namespace

void addBlendCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<BlendArgs>();
    CLI::App* cmd = app.add_subcommand(
        "blend", "Blend two 8-bit images with the exact integer formulas of Tanczos 1999; RGB out");
    cmd->add_option("--mode", args->mode,
                    "alpha: (s*a + d*(255-a))/255; alpha-shift: ... >> 8; premultiplied: s*a/255 + "
                    "((d*(255-a)) >> 8); "
                    "add: min(s + d, 255) (SIMD)")
        ->required()
        ->check(CLI::IsMember(choiceNames(kBlend8ModeNames)));
    cmd->add_option("--src", args->src,
                    "source, 8-bit RGBA (its alpha is the blend alpha; RGB allowed for add)")
        ->required();
    cmd->add_option("--dst", args->dst, "destination, 8-bit RGB or RGBA, same size")->required();
    cmd->add_option("-o,--output", args->out, "output, 8-bit RGB (.png, .tif, .bmp, ...)")
        ->required();
    cmd->callback([args, &exitCode] { exitCode = runBlend(*args); });
}

}  // namespace flarekit::cli
