// SPDX-License-Identifier: Apache-2.0
// One generated sample: lights placed (in and out of frame, suns and point lights at a depth),
// occluders that hide part of them, the flare of a sprite preset, the post-process chain or a
// traced lens prescription, and the camera model.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>

#include "core/Parallel.h"
#include "core/codecs/Codecs.h"
#include "flarekit/Color.h"
#include "flarekit/Flare.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Lens.h"
#include "flarekit/PostFx.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/Shot.h"
#include "flarekit/Synth.h"
#include "flarekit/Tonemap.h"
#include "synth/SynthRandom.h"

namespace flarekit {

namespace {

using nlohmann::json;
using synth_detail::SampleRandom;

// Independent streams of one sample's numbers: adding a draw to one part does not move the
// others' (a camera-model change leaves every light where it was).
enum Stream : std::uint64_t { kLights = 1, kBackground, kOccluders, kFlare, kCamera, kNoise };

struct SynthLight {
    Point at;
    double radius = 1;    //!< px
    Rgb color{1, 1, 1};   //!< luminance 1
    double radiance = 1;  //!< peak, display whites
    bool point = false;
    double depth = 0;     //!< m (point lights)
    double coverage = 1;  //!< visible share of its disc
    bool inFrame = true;
};

//! A light's colour between tungsten, daylight and a cool sky, luminance 1.
Rgb lightColour(SampleRandom& r) {
    const Rgb warm{1.0f, 0.72f, 0.45f}, white{1, 1, 1}, cool{0.82f, 0.9f, 1.0f};
    const double t = r.uniform();
    Rgb c;
    for (int k = 0; k < 3; ++k)
        c[k] = t < 0.5 ? float(warm[k] + (white[k] - warm[k]) * t * 2)
                       : float(white[k] + (cool[k] - white[k]) * (t - 0.5) * 2);
    const double y = luminance(c[0], c[1], c[2]);
    for (float& v : c) v = float(v / y);
    return c;
}

std::vector<SynthLight> drawLights(const SynthConfig& cfg, std::uint64_t seed, std::uint64_t index,
                                   int w, int h, bool centred) {
    SampleRandom r(seed, index, kLights);
    const int n = centred ? 1 : r.integer(cfg.lightsMin, std::max(cfg.lightsMin, cfg.lightsMax));
    std::vector<SynthLight> lights;
    for (int i = 0; i < n; ++i) {
        SynthLight l;
        l.color = lightColour(r);
        l.radiance = r.logRange(cfg.intensityMin, std::max(cfg.intensityMin, cfg.intensityMax));
        l.radius = r.range(cfg.radiusMin, std::max(cfg.radiusMin, cfg.radiusMax)) * h;
        l.point = r.chance(cfg.pointLights);
        if (l.point) {
            // A sphere farther off: its image shrinks as 1/d, its radiance stays, its flux (and
            // so its flare) falls as 1/d^2 through the area.
            l.depth = r.range(cfg.depthMin, std::max(cfg.depthMin, cfg.depthMax));
            l.radius = std::max(0.75, l.radius * cfg.depthMin / l.depth);
        }
        if (centred) {
            l.at = {float(w * 0.5), float(h * 0.5)};
        } else if (r.chance(cfg.offFrame)) {
            // Outside: on a ring of the frame grown by up to the margin, on any side.
            const double mx = w * cfg.offFrameMargin, my = h * cfg.offFrameMargin;
            double x = 0, y = 0;
            do {
                x = r.range(-mx, w + mx), y = r.range(-my, h + my);
            } while (x >= 0 && x < w && y >= 0 && y < h && (mx > 0 || my > 0));
            l.at = {float(x), float(y)};
        } else {
            l.at = {float(r.range(0, w)), float(r.range(0, h))};
        }
        l.inFrame = l.at.x >= 0 && l.at.x < float(w) && l.at.y >= 0 && l.at.y < float(h);
        lights.push_back(l);
    }
    return lights;
}

//! A sky over ground, colours and horizon drawn per sample: cheap, smooth, plausible.
Image proceduralBackground(SampleRandom& r, int w, int h) {
    Image bg(w, h, Image::Uncleared{});
    const double horizon = r.range(0.45, 0.9) * h, level = r.logRange(0.05, 0.8);
    const Rgb zenith{float(r.range(0.2, 0.5)), float(r.range(0.35, 0.6)), float(r.range(0.6, 1))};
    const Rgb haze{float(r.range(0.7, 1)), float(r.range(0.6, 0.9)), float(r.range(0.5, 0.9))};
    const Rgb ground{float(r.range(0.05, 0.3)), float(r.range(0.05, 0.25)),
                     float(r.range(0.03, 0.2))};
    const double tilt = r.range(-0.15, 0.15);
    // The horizon's height in each column and the two gradients' scales there, once per column.
    struct Column {
        double edge, skyScale, groundScale;
    };
    std::vector<Column> columns(static_cast<std::size_t>(w));
    for (int x = 0; x < w; ++x) {
        const double edge = horizon + tilt * (x - w * 0.5);
        columns[std::size_t(x)] = {edge, 1.0 / std::max(edge, 1.0), 1.0 / std::max(h - edge, 1.0)};
    }
    parallelFor(0, h, std::max(1, 16384 / w), [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* row = bg.row(y);
            for (int x = 0; x < w; ++x) {
                const Column& c = columns[std::size_t(x)];
                float* px = row + 4 * x;
                if (y < c.edge) {
                    const double t = std::clamp(y * c.skyScale, 0.0, 1.0);
                    for (int k = 0; k < 3; ++k)
                        px[k] = float(level * (zenith[k] + (haze[k] - zenith[k]) * t * t));
                } else {
                    const double t = std::clamp((y - c.edge) * c.groundScale, 0.0, 1.0);
                    for (int k = 0; k < 3; ++k) px[k] = float(level * ground[k] * (1.0 - 0.5 * t));
                }
                px[3] = 1;
            }
        }
    });
    return bg;
}

//! The image files of a backgrounds folder, sorted (listed once per folder and process).
Result<std::vector<std::string>> backgroundFiles(const std::string& dir) {
    static std::mutex mutex;
    static std::map<std::string, std::vector<std::string>> listed;
    std::lock_guard lock(mutex);
    if (auto it = listed.find(dir); it != listed.end()) return it->second;
    std::vector<std::string> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        std::string ext = entry.path().extension().string();
        for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (entry.is_regular_file(ec) &&
            (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".exr" || ext == ".tif" ||
             ext == ".tiff" || ext == ".hdr" || ext == ".bmp" || ext == ".webp"))
            files.push_back(entry.path().string());
    }
    if (ec)
        return invalidInput(dir + ": backgrounds: cannot list the folder (" + ec.message() + ")");
    std::sort(files.begin(), files.end());
    if (files.empty())
        return invalidInput(dir +
                            ": backgrounds: no image in the folder (png, jpg, exr, tif, hdr)");
    listed[dir] = files;
    return files;
}

//! A random crop of one of the folder's images (its aspect), resized to w x h.
Result<Image> backgroundFrom(const std::string& dir, SampleRandom& r, int w, int h) {
    auto files = backgroundFiles(dir);
    if (!files) return files.error();
    const std::string& file = (*files)[std::size_t(r.next() % files->size())];
    auto loaded = readImage(file);
    if (!loaded) return loaded.error();
    const Image& src = loaded->image;
    const double aspect = double(w) / h;
    const double scale = r.range(0.6, 1.0);
    int cw = std::max(1, int(std::min<double>(src.width(), src.height() * aspect) * scale));
    int ch = std::max(1, int(cw / aspect));
    cw = std::min(cw, src.width()), ch = std::min(ch, src.height());
    const int x0 = r.integer(0, src.width() - cw), y0 = r.integer(0, src.height() - ch);
    Image crop(cw, ch);
    for (int y = 0; y < ch; ++y) std::copy_n(src.row(y0 + y) + 4 * x0, 4 * cw, crop.row(y));
    Image out = resizeBilinear(crop, w, h);
    for (std::size_t i = 0; i < out.pixelCount(); ++i) out.data()[4 * i + 3] = 1;
    return out;
}

//! Discs and boxes (alpha 1) that hide what is behind them; described for the label.
Image occluderMatte(const SynthConfig& cfg, SampleRandom& r, int w, int h, json& shapes) {
    Image matte(w, h);
    const int n = r.integer(1, cfg.occludersMax);
    for (int i = 0; i < n; ++i) {
        const bool disc = r.chance(0.5);
        const double cx = r.range(0, w), cy = r.range(0, h);
        const double a = r.range(0.03, 0.25) * h, b = r.range(0.03, 0.25) * h;
        shapes.push_back(disc ? json{{"shape", "disc"}, {"x", cx}, {"y", cy}, {"radius", a}}
                              : json{{"shape", "box"},
                                     {"x0", cx - a},
                                     {"y0", cy - b},
                                     {"x1", cx + a},
                                     {"y1", cy + b}});
        const int y0 = std::max(0, int(cy - (disc ? a : b))),
                  y1 = std::min(h, int(cy + (disc ? a : b)) + 1);
        const int x0 = std::max(0, int(cx - a)), x1 = std::min(w, int(cx + a) + 1);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
                if (!disc || dx * dx + dy * dy <= a * a) matte.at(x, y).a = 1;
            }
    }
    return matte;
}

//! Each light's disc (soft by half a pixel) and its glare core (falling as (r/d)^3, faded to
//! nothing at 24 radii so no edge shows), hidden where the matte is.
Image lightSources(int w, int h, const std::vector<SynthLight>& lights, const Image* matte) {
    Image out(w, h);
    for (const SynthLight& l : lights) {
        const double reach = 24 * l.radius + 2;
        const int x0 = std::max(0, int(l.at.x - reach)), x1 = std::min(w, int(l.at.x + reach) + 1);
        const int y0 = std::max(0, int(l.at.y - reach)), y1 = std::min(h, int(l.at.y + reach) + 1);
        if (y0 >= y1 || x0 >= x1) continue;
        parallelFor(y0, y1, std::max(1, 16384 / (x1 - x0)), [&](int rowBegin, int rowEnd) {
            for (int y = rowBegin; y < rowEnd; ++y)
                for (int x = x0; x < x1; ++x) {
                    const double dx = x + 0.5 - l.at.x, dy = y + 0.5 - l.at.y;
                    const double d = std::sqrt(dx * dx + dy * dy);
                    const double disc = std::clamp(l.radius + 0.5 - d, 0.0, 1.0);
                    const double fade = std::max(0.0, 1.0 - (d / reach) * (d / reach));
                    const double q = l.radius / std::max(d, l.radius);
                    const double glare = 0.02 * q * q * q * fade * fade;
                    double v = l.radiance * (disc + glare);
                    if (matte) v *= 1.0 - matte->at(x, y).a;
                    Rgba& px = out.at(x, y);
                    px.r += float(v * l.color[0]), px.g += float(v * l.color[1]);
                    px.b += float(v * l.color[2]);
                }
        });
    }
    for (std::size_t i = 0; i < out.pixelCount(); ++i) out.data()[4 * i + 3] = 1;
    return out;
}

//! A light's flux: its disc's radiance summed over its pixels, times the share seen.
double visibleFlux(const SynthLight& l) {
    return l.radiance * 3.141592653589793 * l.radius * l.radius * l.coverage;
}

struct DrawnFlare {
    std::string kind, name;
    json params = json::object();
    Image flare;
    std::vector<std::pair<std::string, Image>> components;
};

template <class Names>
std::string pick(SampleRandom& r, const Names& names) {
    return names[std::size_t(r.next() % names.size())];
}

Result<DrawnFlare> spriteFlare(SampleRandom& r, int w, int h,
                               const std::vector<SynthLight>& lights) {
    DrawnFlare d;
    d.kind = "sprite", d.name = pick(r, shippedPresetNames());
    auto preset = loadPreset(d.name);
    if (!preset) return preset.error();
    std::vector<std::pair<Point, float>> scaled;
    for (const SynthLight& l : lights)
        scaled.push_back({l.at, flareScaleForFlux(visibleFlux(l), h)});
    for (auto& layer : renderFlareLayers(w, h, *preset, scaled, d.flare))
        d.components.push_back({layer.name, std::move(layer.image)});
    return d;
}

Result<DrawnFlare> postFxFlare(SampleRandom& r, const Image& sources) {
    DrawnFlare d;
    d.kind = "postfx", d.name = pick(r, shippedPostFxPresetNames());
    auto params = loadPostFxPreset(d.name);
    if (!params) return params.error();
    params->tone.op = ToneOperator::None, params->tone.exposure = 1;
    // Ghost blur taps symmetric about each point and sampled bilinearly: the seed's one-sided
    // taps and point sampler move a ghost off the line through the centre by up to a pixel of
    // the quarter-resolution buffer, and a training set's ghosts must lie on it.
    for (GhostParams& ghost : params->ghosts)
        ghost.centered = true, ghost.linearFilter = true, ghost.borderFade = 0;
    // The flare is the chain's lens buffer at full size, which its composite would add to the
    // sources: the composite is not drawn (the sample adds the flare itself). Up to a megapixel
    // (training sizes) one chain per thread keeps its buffers and lens dirt between the samples
    // that thread makes, a fifth of a post-process sample's time at 512x512; its buffers hold
    // less than one full-size layer (16 bytes a pixel), inside the sample's memory estimate.
    PostFxOptions options;
    options.keepLayers = true, options.composite = false;
    const int w = sources.width(), h = sources.height();
    constexpr std::size_t kKeptChainPixels = std::size_t(1) << 20;
    thread_local CpuPostFx kept;
    CpuPostFx fresh;
    CpuPostFx& chain = sources.pixelCount() <= kKeptChainPixels ? kept : fresh;
    PostFxResult result;
    if (Status s = chain.run(sources, *params, result, options); !s) return s.error();
    d.flare = resizeBilinear(result.lens, w, h);
    parallelFor(0, h, std::max(1, 16384 / w), [&d, w](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* row = d.flare.row(y);
            for (int i = 0; i < 4 * w; ++i) row[i] = i % 4 == 3 ? 1.f : std::max(0.f, row[i]);
        }
    });
    for (auto [name, layer] : {std::pair{"bloom", &result.bloom},
                               {"ghosts", &result.ghosts},
                               {"halo", &result.halo},
                               {"streaks", &result.streaks}})
        d.components.emplace_back(name, resizeBilinear(*layer, w, h));
    return d;
}

Result<DrawnFlare> lensFlare(SampleRandom& r, const SynthConfig& cfg, int w, int h,
                             const std::vector<SynthLight>& lights) {
    DrawnFlare d;
    d.kind = "lens", d.name = pick(r, lensNames());
    auto lens = loadLens(d.name);
    if (!lens) return lens.error();
    const double open = paraxial(*lens).fNumber;
    const double f = r.logRange(open, std::max(open, cfg.fNumberMax));
    if (f > open * 1.0001) {
        lens = stopDown(*lens, f);
        if (!lens) return lens.error();
    }
    static constexpr const char* kCoatings[] = {"as-designed", "uncoated", "mgf2", "broadband"};
    const int coating = r.integer(0, 3);
    if (coating == 1) lens->coating = {};
    if (coating == 2) lens->coating = coatingDesign(CoatingDesign::Mgf2, kMgF2DesignNm);
    if (coating == 3) lens->coating = coatingDesign(CoatingDesign::Broadband, kMgF2DesignNm);
    lens->aperture.blades = r.integer(5, 9);
    lens->aperture.roundness = r.range(0, 0.6);
    lens->aperture.rotationDeg = r.range(0, 360.0 / lens->aperture.blades);
    d.params = {{"f_number", paraxial(*lens).fNumber},
                {"coating", kCoatings[coating]},
                {"blades", lens->aperture.blades},
                {"roundness", lens->aperture.roundness},
                {"rotation_deg", lens->aperture.rotationDeg}};
    std::vector<LensLight> sources;
    for (const SynthLight& l : lights) {
        const double flux = visibleFlux(l);
        sources.push_back(
            {l.at.x, l.at.y, {flux * l.color[0], flux * l.color[1], flux * l.color[2]}});
    }
    LensRenderOptions options;
    options.ghosts = cfg.lensGhosts;
    auto layers = renderLensFlare(*lens, w, h, sources, options);
    if (!layers) return layers.error();
    d.flare = lensFlareSum(*layers);
    d.components = {{"ghosts", std::move(layers->ghosts)},
                    {"starburst", std::move(layers->starburst)},
                    {"glare", std::move(layers->glare)}};
    return d;
}

//! The camera: exposure (after an auto-exposure of the background), tone curve, shot and read
//! noise, gamma, quantisation; `noise` draws the same pattern for composite and gt.
struct Camera {
    double gain = 1, gamma = 2.2;
    std::uint64_t noiseSeed = 0;
};

Camera drawCamera(const SynthConfig& cfg, SampleRandom& r, const Image& background) {
    Camera c;
    if (cfg.autoExposure) {
        double sum = 0;
        for (std::size_t i = 0; i < background.pixelCount(); ++i)
            sum += luminance(background.data()[4 * i], background.data()[4 * i + 1],
                             background.data()[4 * i + 2]);
        const double mean = sum / double(background.pixelCount());
        if (mean > 0) c.gain = 0.18 / mean;
    }
    c.gain *= std::exp2(r.range(cfg.exposureMin, std::max(cfg.exposureMin, cfg.exposureMax)));
    c.gamma = r.range(cfg.gammaMin, std::max(cfg.gammaMin, cfg.gammaMax));
    c.noiseSeed = r.next();
    return c;
}

void applyCamera(Image& image, const SynthConfig& cfg, const Camera& c) {
    toneMapImage(image, cfg.tone, float(c.gain));
    const float levels = cfg.bits ? float(std::exp2(cfg.bits) - 1) : 0.f;
    const float inverseGamma = float(1.0 / c.gamma);
    const float shot = float(cfg.shotNoise), read = float(cfg.readNoise * cfg.readNoise);
    // Rows in parallel, each with its own noise stream: the same noise on any thread count.
    parallelFor(0, image.height(), 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            SampleRandom noise(c.noiseSeed, std::uint64_t(y), kNoise);
            float* px = image.row(y);
            for (int x = 0; x < image.width(); ++x, px += 4) {
                for (int k = 0; k < 3; ++k) {
                    float v = std::max(0.f, px[k]);
                    const float sigma = std::sqrt(shot * std::min(v, 1.f) + read);
                    if (sigma > 0) v += sigma * float(noise.normal());
                    v = std::pow(std::clamp(v, 0.f, 1.f), inverseGamma);
                    if (levels > 0) v = std::round(v * levels) / levels;
                    px[k] = v;
                }
            }
        }
    });
}

//! a + b in colour; alpha 1 (every layer is opaque).
//! The camera's 8-bit output through JPEG at `quality` and back (libjpeg-turbo, in memory).
Status jpegRoundTrip(Image& image, int quality) {
    const int w = image.width(), h = image.height();
    std::vector<unsigned char> codes(std::size_t(w) * std::size_t(h) * 3);
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        for (int k = 0; k < 3; ++k)
            codes[3 * i + std::size_t(k)] = static_cast<unsigned char>(
                std::lround(image.data()[4 * i + std::size_t(k)] * 255.f));
    codec::Samples samples;
    samples.width = w, samples.height = h, samples.channels = 3;
    samples.type = codec::SampleType::U8, samples.data = codes.data();
    codec::EncodeOptions options;
    options.jpegQuality = quality;
    auto bytes = codec::encodeJpeg(samples, options);
    if (!bytes) return bytes.error();
    auto raw = codec::decodeJpegBytes(*bytes, "the camera model's JPEG",
                                      [](const codec::Header&) { return Status(Ok{}); });
    if (!raw) return raw.error();
    if (raw->channels != 3 || raw->header.width != w || raw->header.height != h)
        return internalError("the camera model's JPEG came back another shape");
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        for (int k = 0; k < 3; ++k)
            image.data()[4 * i + std::size_t(k)] =
                float(raw->bytes[3 * i + std::size_t(k)]) / 255.f;
    return Ok{};
}

//! The clean plate and the flared frame in one pass over rows: gt = background + sources and
//! composite = gt + flare, both opaque.
void compose(const Image& background, const Image& sources, const Image& flare, Image& gt,
             Image& composite) {
    const int w = background.width();
    gt = Image(w, background.height(), Image::Uncleared{});
    composite = Image(w, background.height(), Image::Uncleared{});
    parallelFor(0, background.height(), std::max(1, 16384 / w), [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float *b = background.row(y), *s = sources.row(y), *f = flare.row(y);
            float *g = gt.row(y), *c = composite.row(y);
            for (int i = 0; i < 4 * w; i += 4) {
                for (int k = 0; k < 3; ++k) {
                    g[i + k] = b[i + k] + s[i + k];
                    c[i + k] = g[i + k] + f[i + k];
                }
                g[i + 3] = c[i + 3] = 1.f;
            }
        }
    });
}

}  // namespace

const Image* SynthSample::layer(const std::string& name) const {
    for (const auto& [n, image] : layers)
        if (n == name) return &image;
    return nullptr;
}

Result<SynthSample> synthSample(std::uint64_t index, std::uint64_t seed, int width, int height,
                                const SynthConfig& cfg, bool centred) {
    if (width < 1 || height < 1 || width > kMaxSynthSide || height > kMaxSynthSide)
        return invalidInput("size: expected W x H from 1 to " + std::to_string(kMaxSynthSide) +
                            " pixels a side, got " + std::to_string(width) + "x" +
                            std::to_string(height));
    const int w = width, h = height;
    std::vector<SynthLight> lights = drawLights(cfg, seed, index, w, h, centred);

    SampleRandom backgroundRandom(seed, index, kBackground);
    Image background;
    if (centred) {
        background = Image(w, h);
        for (std::size_t i = 0; i < background.pixelCount(); ++i) background.data()[4 * i + 3] = 1;
    } else if (!cfg.backgrounds.empty()) {
        auto bg = backgroundFrom(cfg.backgrounds, backgroundRandom, w, h);
        if (!bg) return bg.error();
        background = std::move(*bg);
    } else {
        background = proceduralBackground(backgroundRandom, w, h);
    }

    // Occluders hide part of the lights: each light's coverage is the matte's mean visibility
    // over its disc (the shots' coverage), which dims its whole flare.
    SampleRandom occluderRandom(seed, index, kOccluders);
    json shapes = json::array();
    std::optional<Image> matte;
    if (!centred && occluderRandom.chance(cfg.occluded)) {
        matte = occluderMatte(cfg, occluderRandom, w, h, shapes);
        for (SynthLight& l : lights)
            l.coverage = discVisibility(*matte, Occluder{}, l.at, l.radius);
        const float shade = float(occluderRandom.range(0.01, 0.08));
        for (std::size_t i = 0; i < background.pixelCount(); ++i) {
            const float a = matte->data()[4 * i + 3];
            for (int k = 0; k < 3; ++k) {
                float& v = background.data()[4 * i + k];
                v = v * (1 - a) + shade * a;
            }
        }
    }
    Image sources = lightSources(w, h, lights, matte ? &*matte : nullptr);

    SampleRandom flareRandom(seed, index, kFlare);
    const double total = cfg.spriteWeight + cfg.postfxWeight + cfg.lensWeight;
    const double pickKind = flareRandom.uniform() * total;
    Result<DrawnFlare> drawn = pickKind < cfg.spriteWeight ? spriteFlare(flareRandom, w, h, lights)
                               : pickKind < cfg.spriteWeight + cfg.postfxWeight
                                   ? postFxFlare(flareRandom, sources)
                                   : lensFlare(flareRandom, cfg, w, h, lights);
    if (!drawn) return drawn.error();

    SynthSample sample;
    Image gt, composite;
    compose(background, sources, drawn->flare, gt, composite);
    json camera = nullptr;
    if (cfg.camera) {
        SampleRandom cameraRandom(seed, index, kCamera);
        const Camera c = drawCamera(cfg, cameraRandom, background);
        applyCamera(composite, cfg, c);
        applyCamera(gt, cfg, c);
        if (cfg.jpegQuality > 0) {
            for (Image* image : {&composite, &gt})
                if (Status s = jpegRoundTrip(*image, cfg.jpegQuality); !s) return s.error();
        }
        sample.gamma = c.gamma;
        camera = {{"gain", c.gain},
                  {"gamma", c.gamma},
                  {"tone", std::string(kToneOperatorNames[int(cfg.tone)])},
                  {"shot_noise", cfg.shotNoise},
                  {"read_noise", cfg.readNoise},
                  {"bits", cfg.bits},
                  {"jpeg_quality", cfg.jpegQuality}};
    }

    json label = {{"index", index}, {"seed", seed}, {"width", w}, {"height", h}};
    json lightList = json::array();
    for (const SynthLight& l : lights)
        lightList.push_back({{"x", l.at.x},
                             {"y", l.at.y},
                             {"in_frame", l.inFrame},
                             {"kind", l.point ? "point" : "sun"},
                             {"depth", l.point ? json(l.depth) : json(nullptr)},
                             {"radius", l.radius},
                             {"radiance", l.radiance},
                             {"color", {l.color[0], l.color[1], l.color[2]}},
                             {"coverage", l.coverage}});
    label["lights"] = lightList;
    json flare = {{"kind", drawn->kind}, {drawn->kind == "lens" ? "lens" : "preset", drawn->name}};
    flare.update(drawn->params);
    json components = json::array();
    for (const auto& [name, image] : drawn->components) components.push_back(name);
    flare["components"] = components;
    label["flare"] = flare;
    label["occluders"] = shapes;
    label["camera"] = camera;
    label["gamma"] = sample.gamma;
    sample.label = label.dump();

    sample.layers.push_back({"background", std::move(background)});
    sample.layers.push_back({"light_source", std::move(sources)});
    sample.layers.push_back({"flare", std::move(drawn->flare)});
    for (auto& component : drawn->components) sample.layers.push_back(std::move(component));
    sample.layers.push_back({"gt", std::move(gt)});
    sample.layers.push_back({"composite", std::move(composite)});
    return sample;
}

}  // namespace flarekit
