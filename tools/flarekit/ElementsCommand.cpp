// flarekit elements: a labelled contact sheet of a preset's elements.
#include "Common.h"
#include "flarekit/ImageIO.h"

namespace flarekit::cli {

namespace {
struct ElementsArgs {
    std::string preset = "tanczos-classic", out;
    int cell = 256;
};

int runElements(const ElementsArgs& a) {
    if (Status s = checkOutputPath(a.out); !s) return report(s.error());
    auto preset = loadPreset(a.preset);
    if (!preset) return report(preset.error());
    auto sheet = renderContactSheet(*preset, a.cell);
    if (!sheet) return report(sheet.error());
    if (!sheet->labelled) warn("no font found for the labels (install fonts-dejavu-core); sheet written without them");
    if (Status s = writeImage(a.out, sheet->image); !s) return report(s.error());
    return kExitOk;
}
}  // namespace

void addElementsCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<ElementsArgs>();
    CLI::App* cmd = app.add_subcommand("elements", "Render a preset's elements as a labelled contact sheet");
    cmd->add_option("--preset", args->preset, "shipped preset name or a JSON file")->capture_default_str();
    cmd->add_option("-o,--output", args->out, "output image")->required();
    cmd->add_option("--cell", args->cell, "cell size in pixels")->check(CLI::Range(32, 4096))->capture_default_str();
    cmd->callback([args, &exitCode] { exitCode = runElements(*args); });
}

}  // namespace flarekit::cli
