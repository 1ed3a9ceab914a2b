// SPDX-License-Identifier: Apache-2.0
// flarekit convert IN -o OUT [--from FORMAT] [--to FORMAT]: flares between flarekit presets and
// PlayCanvas, Babylon.js, three.js, Unity, Unreal and Godot (flarekit/Convert.h; the formats
// and their conventions in docs/interop.md).
#include <cstdio>

#include "Common.h"
#include "ParamOptions.h"
#include "flarekit/Convert.h"

namespace flarekit::cli {

namespace {
struct ConvertArgs {
    std::string input, output, from, to;
    ConvertOptions options;
};

int runConvert(ConvertArgs& a) {
    if (!a.from.empty()) a.options.from = parseFlareFormat(a.from);
    if (!a.to.empty()) a.options.to = parseFlareFormat(a.to);
    auto warnings = convertFlare(a.input, a.output, a.options);
    if (!warnings) return report(warnings.error());
    for (const std::string& w : *warnings) warn(w);
    return kExitOk;
}
}  // namespace

void addConvertCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<ConvertArgs>();
    CLI::App* cmd = app.add_subcommand(
        "convert",
        "Convert flares between flarekit presets and PlayCanvas, Babylon.js, three.js, Unity "
        "(sprite flares) and Unreal, Godot (post-process flares); see docs/interop.md");
    cmd->add_option("input", args->input, "the flare file to read")->required();
    cmd->add_option("-o,--output", args->output,
                    "the file to write (its textures are written beside it)")
        ->required();
    const std::vector<std::string> formats = choiceNames(kFlareFormatNames);
    cmd->add_option("--from", args->from,
                    "the input's format (default: from its extension and content)")
        ->check(CLI::IsMember(formats));
    cmd->add_option("--to", args->to,
                    "the output's format (default: from its extension: .asset unity, .tscn "
                    "godot, .ini unreal; .json needs --to)")
        ->check(CLI::IsMember(formats));
    const std::span<const Param<ConvertOptions>> table(kConvertParams);
    addParamOption(cmd, table, "aspect", args->options);
    addParamOption(cmd, table, "reference_height", args->options);
    addParamChoice(cmd, table, "unity_blend_order", args->options);
    cmd->add_option("--unity-assets", args->options.unityAssets,
                    "folder searched for the .meta files of a Unity asset's textures (default: "
                    "the asset's project Assets folder, or its own folder)");
    cmd->callback([args, &exitCode] { exitCode = runConvert(*args); });
}

}  // namespace flarekit::cli
