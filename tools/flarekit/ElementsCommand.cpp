// SPDX-License-Identifier: Apache-2.0
// flarekit elements: a labelled contact sheet of a preset's elements.
#include "Common.h"
#include "ParamOptions.h"
#include "flarekit/ImageIO.h"

namespace flarekit::cli {

namespace {
struct ElementsArgs {
    std::string preset = kDefaultSpritePreset, out;
    int cell = 256;
};
//! 32 px is the smallest cell a label fits in; 4096 bounds the sheet at 4096 x (elements) cells.
inline constexpr Param<ElementsArgs> kElementsArgParams[] = {
    param<&ElementsArgs::cell>("cell", 32, 4096, "pixels", "cell size"),
};

int runElements(const ElementsArgs& a) {
    return runImageJob(a.out, [&]() -> Result<ImageOutput> {
        auto preset = loadPreset(a.preset);
        if (!preset) return preset.error();
        if (Status s = checkFlareWork(*preset, a.cell, a.cell, 1, a.preset); !s) return s.error();
        auto sheet = renderContactSheet(*preset, a.cell);
        if (!sheet) return sheet.error();
        if (!sheet->labelled)
            warn(
                "no font found for the labels (install fonts-dejavu-core); sheet written without "
                "them");
        return ImageOutput{std::move(sheet->image), {}};
    });
}
}  // namespace

void addElementsCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<ElementsArgs>();
    CLI::App* cmd =
        app.add_subcommand("elements", "Render a preset's elements as a labelled contact sheet");
    cmd->add_option("--preset", args->preset, "shipped preset name or a JSON file")
        ->capture_default_str();
    cmd->add_option("-o,--output", args->out, "output image")->required();
    addParamOptions<ElementsArgs>(cmd, kElementsArgParams, *args);
    cmd->callback([args, &exitCode] { exitCode = runElements(*args); });
}

}  // namespace flarekit::cli
