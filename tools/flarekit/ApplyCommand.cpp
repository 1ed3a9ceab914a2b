// flarekit apply: composite a preset's sprite flare onto an image, in linear light.
#include <cstdio>

#include "Common.h"
#include "ParamOptions.h"
#include "flarekit/ImageIO.h"

namespace flarekit::cli {

namespace {
struct ApplyArgs {
    std::string in, out, preset = "tanczos-classic", light = "auto", depth = "auto";
    float intensity = 1.f;
    LightSearchOptions lightSearch;
    bool verbose = false;
};
inline constexpr Param<ApplyArgs> kApplyArgParams[] = {
    param<&ApplyArgs::intensity>("intensity", 0, 1000, "", "flare brightness multiplier"),
};

std::optional<SampleFormat> parseDepth(const std::string& s) {
    if (s == "auto") return SampleFormat::Auto;
    if (s == "8") return SampleFormat::U8;
    if (s == "16") return SampleFormat::U16;
    if (s == "half") return SampleFormat::Half;
    if (s == "float") return SampleFormat::Float;
    return std::nullopt;
}

int runApply(const ApplyArgs& a) {
    if (Status s = checkOutputPath(a.out); !s) return report(s.error());
    const bool autoLight = a.light == "auto";
    const std::optional<Point> fixed = autoLight ? std::nullopt : parsePoint(a.light);
    if (!autoLight && !fixed) return report(invalidInput("--light: expected X,Y in pixels or 'auto', got '" + a.light + "'"));
    auto preset = loadPreset(a.preset);
    if (!preset) return report(preset.error());
    auto loaded = readQuietly(readImage, a.in);
    if (!loaded) return report(loaded.error());
    if (loaded->nonFinite > 0) warn(a.in + ": " + std::to_string(loaded->nonFinite) + " NaN/Inf values replaced by 0");
    if (loaded->droppedChannels > 0) {
        warn(a.in + ": " + std::to_string(loaded->droppedChannels) + " channel(s) past RGBA are not written to the output");
    }

    Image& image = loaded->image;
    Point light{};
    float intensity = a.intensity;
    if (fixed) {
        light = *fixed;
    } else {
        const LightSearchOptions& options = a.lightSearch;
        const FoundLight found = findLight(image, options);
        if (!found.found) {
            warn(a.in + ": no light found (peak luminance " + std::to_string(found.peak) + " < " +
                 std::to_string(options.minLuminance) + "); image written unchanged");
        } else {
            light = found.position;
            intensity *= found.flareScale;
            if (a.verbose) {
                std::printf("light at %.1f,%.1f: %zu pixels, brightness %.3f, flare scale %.3f\n", double(light.x),
                            double(light.y), found.pixels, double(found.brightness), double(found.flareScale));
            }
        }
        if (!found.found) intensity = 0.f;
    }
    if (intensity > 0.f) {
        const FlareStats stats = renderFlare(image, *preset, light, intensity);
        if (a.verbose) std::printf("%zu elements, %zu pixels shaded\n", stats.elementsDrawn, stats.pixelsShaded);
    }
    WriteOptions options;
    options.alpha = loaded->hasAlpha;
    options.format = *parseDepth(a.depth);
    if (Status s = writeImage(a.out, image, options); !s) return report(s.error());
    return kExitOk;
}
}  // namespace

void addApplyCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<ApplyArgs>();
    CLI::App* cmd = app.add_subcommand("apply", "Put a sprite lens flare on an image (linear-light additive compositing)");
    cmd->add_option("input", args->in, "input image (EXR, PNG, JPEG, TIFF, ...; 8-bit files are sRGB-decoded)")->required();
    cmd->add_option("-o,--output", args->out, "output image; format and bit depth follow the extension")->required();
    cmd->add_option("--preset", args->preset, "shipped preset name (see `flarekit presets`) or a JSON file")
        ->capture_default_str();
    cmd->add_option("--light", args->light,
                    "light position X,Y in pixels from the top-left (may be outside the frame), or 'auto' for the "
                    "brightest region")
        ->capture_default_str();
    addParamOptions<ApplyArgs>(cmd, kApplyArgParams, *args);
    addParamOptions<LightSearchOptions>(cmd, kLightSearchParams, args->lightSearch);
    cmd->add_option("--depth", args->depth, "output samples: auto (from the extension), 8, 16, half, float")
        ->check(CLI::IsMember({"auto", "8", "16", "half", "float"}))
        ->capture_default_str();
    cmd->add_flag("-v,--verbose", args->verbose, "print the light found and the work done");
    cmd->callback([args, &exitCode] { exitCode = runApply(*args); });
}

}  // namespace flarekit::cli
