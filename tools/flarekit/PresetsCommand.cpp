// SPDX-License-Identifier: Apache-2.0
// flarekit presets: list the shipped presets, validate a preset file, or print the parameter
// reference generated from the table that validates presets.
#include <cstdio>

#include "Common.h"
#include "flarekit/PostFx.h"

namespace flarekit::cli {

namespace {
struct PresetsArgs {
    bool params = false, postfx = false;
    std::string check;
};

//! The same three jobs for the post-process presets (presets/postfx/).
int runPostFxPresets(const PresetsArgs& a) {
    if (a.params) {
        std::fputs(postFxParameterReference().c_str(), stdout);
        return kExitOk;
    }
    if (!a.check.empty()) {
        auto preset = loadPostFxPreset(a.check);
        if (!preset) return report(preset.error());
        std::printf("%s: ok, %zu ghosts\n", a.check.c_str(), preset->ghosts.size());
        return kExitOk;
    }
    for (const std::string& name : shippedPostFxPresetNames()) {
        auto preset = loadPostFxPreset(name);
        if (!preset) return report(preset.error());
        std::printf("%-18s %2zu ghosts  %s\n", name.c_str(), preset->ghosts.size(),
                    preset->description.c_str());
    }
    return kExitOk;
}

int runPresets(const PresetsArgs& a) {
    if (a.postfx) return runPostFxPresets(a);
    if (a.params) {
        std::fputs(presetParameterReference().c_str(), stdout);
        return kExitOk;
    }
    if (!a.check.empty()) {
        auto preset = loadPreset(a.check);
        if (!preset) return report(preset.error());
        std::printf("%s: ok, %zu elements\n", a.check.c_str(), preset->elements.size());
        return kExitOk;
    }
    for (const std::string& name : shippedPresetNames()) {
        auto preset = loadPreset(name);
        if (!preset) return report(preset.error());
        std::printf("%-18s %2zu elements  %s\n", name.c_str(), preset->elements.size(),
                    preset->description.c_str());
    }
    return kExitOk;
}
}  // namespace

void addPresetsCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<PresetsArgs>();
    CLI::App* cmd = app.add_subcommand(
        "presets", "List shipped presets, check a preset file, or print the parameter reference");
    cmd->add_flag("--params", args->params, "print every element parameter (Markdown table)");
    cmd->add_option("--check", args->check, "validate a preset (name or file) and report");
    cmd->add_flag("--postfx", args->postfx,
                  "the same for the post-process presets of `flarekit postfx`");
    cmd->callback([args, &exitCode] { exitCode = runPresets(*args); });
}

}  // namespace flarekit::cli
