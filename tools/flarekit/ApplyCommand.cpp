// flarekit apply: composite a preset's sprite flare onto an image, in linear light.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "Common.h"
#include "ParamOptions.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Tonemap.h"

namespace flarekit::cli {

namespace {
struct ApplyArgs {
    std::string in, out, preset = kDefaultSpritePreset, light = "auto", depth = "auto",
                         tonemap = "auto";
    float intensity = 1.f, exposure = 1.f;
    LightSearchOptions lightSearch;
    bool verbose = false;
};
inline constexpr Param<ApplyArgs> kApplyArgParams[] = {
    param<&ApplyArgs::intensity>("intensity", 0, 1000, "", "flare brightness multiplier"),
    param<&ApplyArgs::exposure>("exposure", 0, 1000, "",
                                "multiplies the image (flare included) before the display curve"),
};

//! Checked before any work: writeImage would refuse at the end (holdsFloatSamples).
Status checkDepthFits(const std::string& out, SampleFormat requested) {
    if (!isFloatFormat(requested) || holdsFloatSamples(out)) return Ok{};
    return invalidInput(out +
                        ": --depth half/float needs a float format (.exr, .tif, .hdr), not '" +
                        std::filesystem::path(out).extension().string() + "'");
}

std::optional<SampleFormat> parseDepth(const std::string& s) {
    if (s == "auto") return SampleFormat::Auto;
    if (s == "8") return SampleFormat::U8;
    if (s == "16") return SampleFormat::U16;
    if (s == "half") return SampleFormat::Half;
    if (s == "float") return SampleFormat::Float;
    return std::nullopt;
}

//! -v: every region --light auto considered, most flux first.
void printCandidates(const LightSearch& search) {
    std::vector<LightCandidate> sorted = search.candidates;
    std::stable_sort(
        sorted.begin(), sorted.end(),
        [](const LightCandidate& a, const LightCandidate& b) { return a.flux > b.flux; });
    std::printf(
        "peak luminance %.4g, median %.4g, %s; %zu candidates (most flux first, at most 12 "
        "listed):\n",
        double(search.peak), double(search.frameKey),
        search.displayReferred ? "display-referred (clipped pixels x clipped-gain)"
                               : "scene-referred HDR",
        sorted.size());
    //! Candidates listed at most: the lights and the closest misses, not every speck of sky.
    constexpr std::size_t kListed = 12;
    if (sorted.size() > kListed) sorted.resize(kListed);
    for (const LightCandidate& c : sorted)
        std::printf(
            "  at %.1f,%.1f radius %.1f px, peak %.4g, flux %.4g, %.2fx surroundings, "
            "compactness %.2f, halo %.2f, flare scale %.4f: %s\n",
            double(c.position.x), double(c.position.y), double(c.radius), double(c.peak), c.flux,
            double(c.prominence), double(c.compactness), double(c.halo), double(c.flareScale),
            c.verdict.c_str());
}

Result<ImageOutput> applyFlare(const ApplyArgs& a) {
    const bool autoLight = a.light == "auto";
    const std::optional<Point> fixed = autoLight ? std::nullopt : parsePoint(a.light);
    if (!autoLight && !fixed)
        return invalidInput("--light: expected X,Y in pixels or 'auto', got '" + a.light + "'");
    const SampleFormat depth = *parseDepth(a.depth);
    if (Status s = checkDepthFits(a.out, depth); !s) return s.error();
    auto preset = loadPreset(a.preset);
    if (!preset) return preset.error();
    // Measured peak (12 MP, both depths): ~135 MiB of process plus ~43 bytes per pixel: the
    // RGBA floats, the orientation copy, the encoded samples and the file bytes (plus the decode
    // buffer, which readImage adds).
    auto loaded = readInputImage(a.in, {40, 160.0 * (1 << 20), "apply: 40 bytes per pixel"});
    if (!loaded) return loaded.error();
    Image& image = loaded->image;
    std::vector<std::pair<Point, float>> flares;  // position, intensity
    if (fixed) {
        flares.push_back({*fixed, a.intensity});
    } else {
        const LightSearch search = findLights(image, a.lightSearch);
        if (a.verbose) printCandidates(search);
        if (search.lights.empty())
            warn(a.in + ": " + search.whyNone +
                 "; image written unchanged (--light X,Y places one)");
        for (const LightCandidate& light : search.lights)
            flares.push_back({light.position, a.intensity * light.flareScale});
    }
    if (Status s =
            checkFlareWork(*preset, image.width(), image.height(), int(flares.size()), a.preset);
        !s) {
        return s.error();
    }
    for (const auto& [light, intensity] : flares) {
        if (!(intensity > 0.f)) continue;
        const FlareStats stats = renderFlare(image, *preset, light, intensity);
        if (a.verbose)
            std::printf("flare at %.1f,%.1f, intensity %.4f: %zu elements, %zu pixels shaded\n",
                        double(light.x), double(light.y), double(intensity), stats.elementsDrawn,
                        stats.pixelsShaded);
    }
    // --tonemap auto: defaultDisplayCurve (filmic for HDR input to an 8/16-bit file).
    const ToneOperator curve =
        namedToneOperator(a.tonemap).value_or(defaultDisplayCurve(loaded->wasFloat, a.out, depth));
    toneMapImage(image, curve, a.exposure);
    ImageOutput out{std::move(image), {}};
    out.options.alpha = loaded->hasAlpha;
    out.options.format = depth;
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
    cmd->add_option("--tonemap", args->tonemap,
                    "display curve: auto (filmic for HDR input to an 8/16-bit file, else none), "
                    "none, aces, filmic")
        ->check(CLI::IsMember({"auto", "none", "aces", "filmic"}))
        ->capture_default_str();
    cmd->add_flag("-v,--verbose", args->verbose,
                  "print every light candidate (position, radius, flux, score) and the work done");
    cmd->callback([args, &exitCode] { exitCode = runApply(*args); });
}

}  // namespace flarekit::cli
