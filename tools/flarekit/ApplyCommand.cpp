// flarekit apply: composite a preset's sprite flare onto an image, in linear light.
#include <cstdio>

#include "Common.h"
#include "ParamOptions.h"
#include "flarekit/ImageIO.h"

namespace flarekit::cli {

namespace {
struct ApplyArgs {
    std::string in, out, preset = kDefaultSpritePreset, light = "auto", depth = "auto";
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

Result<ImageOutput> applyFlare(const ApplyArgs& a) {
    const bool autoLight = a.light == "auto";
    const std::optional<Point> fixed = autoLight ? std::nullopt : parsePoint(a.light);
    if (!autoLight && !fixed)
        return invalidInput("--light: expected X,Y in pixels or 'auto', got '" + a.light + "'");
    auto preset = loadPreset(a.preset);
    if (!preset) return preset.error();
    auto loaded = readInputImage(a.in);
    if (!loaded) return loaded.error();
    Image& image = loaded->image;
    Point light{};
    float intensity = a.intensity;
    if (fixed) {
        light = *fixed;
    } else {
        const FoundLight found = findLight(image, a.lightSearch);
        if (!found.found) {
            warn(a.in + ": no light found (peak luminance " + std::to_string(found.peak) + " < " +
                 std::to_string(a.lightSearch.minLuminance) + "); image written unchanged");
            intensity = 0.f;
        } else {
            light = found.position;
            intensity *= found.flareScale;
            if (a.verbose) {
                std::printf("light at %.1f,%.1f: %zu pixels, brightness %.3f, flare scale %.3f\n",
                            double(light.x), double(light.y), found.pixels,
                            double(found.brightness), double(found.flareScale));
            }
        }
    }
    if (intensity > 0.f) {
        const FlareStats stats = renderFlare(image, *preset, light, intensity);
        if (a.verbose)
            std::printf("%zu elements, %zu pixels shaded\n", stats.elementsDrawn,
                        stats.pixelsShaded);
    }
    ImageOutput out{std::move(image), {}};
    out.options.alpha = loaded->hasAlpha;
    out.options.format = *parseDepth(a.depth);
    return out;
}

int runApply(const ApplyArgs& a) {
    return runImageJob(a.out, [&] { return applyFlare(a); });
}
}  // namespace

void addApplyCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<ApplyArgs>();
    CLI::App* cmd = app.add_subcommand(
        "apply", "Put a sprite lens flare on an image (linear-light additive compositing)");
    cmd->add_option("input", args->in,
                    "input image (EXR, PNG, JPEG, TIFF, ...; 8-bit files are sRGB-decoded)")
        ->required();
    cmd->add_option("-o,--output", args->out,
                    "output image; format and bit depth follow the extension")
        ->required();
    cmd->add_option("--preset", args->preset,
                    "shipped preset name (see `flarekit presets`) or a JSON file")
        ->capture_default_str();
    cmd->add_option("--light", args->light,
                    "light position X,Y in pixels from the top-left (may be outside the frame), or "
                    "'auto' for the "
                    "brightest region")
        ->capture_default_str();
    addParamOptions<ApplyArgs>(cmd, kApplyArgParams, *args);
    addParamOptions<LightSearchOptions>(cmd, kLightSearchParams, args->lightSearch);
    cmd->add_option("--depth", args->depth,
                    "output samples: auto (from the extension), 8, 16, half, float")
        ->check(CLI::IsMember({"auto", "8", "16", "half", "float"}))
        ->capture_default_str();
    cmd->add_flag("-v,--verbose", args->verbose, "print the light found and the work done");
    cmd->callback([args, &exitCode] { exitCode = runApply(*args); });
}

}  // namespace flarekit::cli
