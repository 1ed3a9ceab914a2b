// SPDX-License-Identifier: Apache-2.0
// flarekit apply: the library's sprite-flare job (flarekit/job/ApplyJob.h) from the command line.
#include <cmath>
#include <cstdio>

#include "Common.h"
#include "JobOptions.h"
#include "ParamOptions.h"
#include "flarekit/job/ApplyJob.h"

namespace flarekit::cli {

namespace {
//! The words of the command line that the library takes typed.
struct ApplyText {
    std::string light = "auto", depth = "auto", tonemap = "auto", lightWorld, sunDir;
    OcioSettings color;
};

std::optional<SampleFormat> parseDepth(const std::string& s) {
    const int i = choiceIndex(kSampleFormatNames, s);
    return i < 0 ? std::nullopt : std::optional<SampleFormat>(SampleFormat(i));
}

//! "X,Y,Z" (three finite numbers) for `option`; a sun direction must not be all 0.
Result<std::optional<Vec3>> parseVec3Option(const std::string& text, const char* option,
                                            bool direction) {
    if (text.empty()) return std::optional<Vec3>();
    double v[3];
    char end = 0;
    bool ok = std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &end) == 3;
    for (double c : v) ok = ok && std::isfinite(c);
    if (ok && direction) ok = length(Vec3{v[0], v[1], v[2]}) > 0;
    if (!ok)
        return invalidInput(std::string(option) + ": expected X,Y,Z (three finite numbers" +
                            (direction ? ", not all 0" : "") + "), got '" + text + "'");
    return std::optional<Vec3>(Vec3{v[0], v[1], v[2]});
}

//! The typed options from the words; errors name the flag.
Status readText(const ApplyText& t, ApplyOptions& o) {
    if (t.light != "auto") {
        o.light = parsePoint(t.light);
        if (!o.light)
            return invalidInput("--light: expected X,Y in pixels or 'auto', got '" + t.light + "'");
    }
    o.depth = *parseDepth(t.depth);
    o.tonemap = toneOperatorNamed(t.tonemap);
    auto world = parseVec3Option(t.lightWorld, "--light-world", false);
    if (!world) return world.error();
    auto sun = parseVec3Option(t.sunDir, "--sun-dir", true);
    if (!sun) return sun.error();
    o.lightWorld = *world;
    o.sunDir = *sun;
    auto color = createOcioTransform(t.color);
    if (!color) return color.error();
    o.color = *color;
    return Ok{};
}

int runApply(const ApplyText& text, ApplyOptions options) {
    if (Status s = readText(text, options); !s) return report(s.error());
    options.encode = encodeSettings();
    CliRun run("apply");
    return run.finish(runApplyJob(options, run.events()));
}
}  // namespace

void addApplyCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<ApplyOptions>();
    auto text = std::make_shared<ApplyText>();
    CLI::App* cmd = app.add_subcommand(
        "apply", "Put a sprite lens flare on an image (linear-light additive compositing)");
    cmd->add_option("input", args->input,
                    "input image (EXR, PNG, JPEG, TIFF, ...; 8-bit files are sRGB-decoded), or a "
                    "frame pattern (shot.####.exr, shot.%04d.exr) for a sequence")
        ->required();
    cmd->add_option("-o,--output", args->output,
                    "output image (a frame pattern for a sequence); format and bit depth follow "
                    "the extension")
        ->required();
    cmd->add_option("--preset", args->preset,
                    "shipped preset name (see `flarekit presets`) or a JSON file")
        ->capture_default_str();
    cmd->add_option("--light", text->light,
                    "light position X,Y in pixels from the top-left (may be outside the frame), or "
                    "'auto' for the brightest region")
        ->capture_default_str();
    addParamOptions<ApplyOptions>(cmd, kApplyParams, *args);
    addParamChoice<ApplyOptions>(cmd, kApplyParams, "flux_mode", *args);
    addParamOptions<LightSearchOptions>(cmd, kLightSearchParams, args->lightSearch);
    cmd->add_option("--depth", text->depth,
                    "output samples: auto (from the extension), 8, 16, half, float")
        ->check(CLI::IsMember(choiceNames(kSampleFormatNames)))
        ->capture_default_str();
    cmd->add_option("--tonemap", text->tonemap,
                    "display curve: auto (filmic for HDR input to an 8/16-bit file, else none), "
                    "none, aces, filmic")
        ->check(CLI::IsMember(toneChoices({"auto"})))
        ->capture_default_str();
    cmd->add_option("--layers", args->layersDir,
                    "also write the flare over black (flare.exr: linear, unclamped, float) and "
                    "its passes (glow, halo, ghosts, streaks, starburst: those the preset has) "
                    "into DIR; the output is then exactly input + flare; for a sequence "
                    "DIR/flare.1001.exr, ...");
    cmd->add_flag("--flare-only", args->flareOnly,
                  "write the flare alone over black (linear unless --tonemap names a curve), to "
                  "add or screen over the plate in the compositing package");
    cmd->add_option("--write-track", args->writeTrack,
                    "a sequence: save where the light was each frame (CSV frame,x,y,intensity, "
                    "what --light-track reads), to edit and feed back; merged with the rows "
                    "other chunks wrote");
    cmd->add_option("--camera", args->camera,
                    "a sequence: the camera per frame (JSON: {\"frames\": [{\"frame\": 1001, "
                    "\"position\", \"look_at\", \"up\", \"fov_y_deg\"}, ...]}, a scene's "
                    "camera form), with --light-world or --sun-dir: the light projected each "
                    "frame; none behind the camera, faded over --guard-band at the frame's edge");
    cmd->add_option("--light-world", text->lightWorld, "with --camera: the light's point X,Y,Z");
    cmd->add_option("--sun-dir", text->sunDir,
                    "with --camera: the direction X,Y,Z toward a distant light (the sun)");
    cmd->add_option("--light-track", args->lightTrack,
                    "the light per frame of a sequence: CSV (frame,x,y or frame,x,y,intensity; "
                    "pixels from the top-left, centres at +0.5) or JSON; linear between keys, the "
                    "end keys held outside them");
    addPartOption(cmd, args->part);
    addLayersInOutputOption(cmd, args->layersInOutput);
    addShotOptions(cmd, args->shot);
    addOcclusionOptions(cmd, args->occlusion);
    addColorOptions(cmd, text->color);
    cmd->add_flag("-v,--verbose", args->verbose,
                  "print every light candidate (position, radius, flux, score) and the work done");
    cmd->callback([args, text, &exitCode] { exitCode = runApply(*text, *args); });
}

}  // namespace flarekit::cli
