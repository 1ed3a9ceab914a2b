// SPDX-License-Identifier: Apache-2.0
// `flarekit synth`: a shard of a sample set written in one of three layouts, each sample's
// files atomically and its label last, so an interrupted run leaves only complete samples and
// --resume finishes the set exactly as an uninterrupted run would have.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/JsonText.h"
#include "core/SafeWrite.h"
#include "flarekit/Color.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Limits.h"
#include "flarekit/Synth.h"

namespace flarekit {

namespace {

namespace fs = std::filesystem;

std::string sampleName(std::uint64_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "%06llu", static_cast<unsigned long long>(index));
    return name;
}

std::string labelPath(const std::string& out, std::uint64_t index) {
    return (fs::path(out) / "labels" / (sampleName(index) + ".json")).string();
}

//! The set's identity, recorded in the folder: a second run adds to it only when it matches.
std::string manifestText(const SynthRunOptions& o) {
    nlohmann::json m = {
        {"seed", o.seed},     {"width", o.width},
        {"height", o.height}, {"format", std::string(kSynthFormatNames[int(o.format)])},
        {"depth", o.depth},   {"config", nlohmann::json::parse(synthConfigJson(o.config))}};
    return m.dump(2) + "\n";
}

Status claimFolder(const SynthRunOptions& o) {
    if (Status s = makeOutputDirectory(o.out); !s) return s;
    const std::string path = (fs::path(o.out) / "synth-manifest.json").string();
    const std::string mine = manifestText(o);
    std::error_code ec;
    if (fs::exists(path, ec)) {
        auto theirs = readTextFile(path);
        if (!theirs) return theirs.error();
        if (*theirs == mine) return Ok{};
        auto m = parseJsonText(*theirs, path);
        std::string what = "another set";
        if (m && m->is_object() && m->contains("seed"))
            what = "the samples of seed " + m->at("seed").dump() + " (" +
                   m->value("format", std::string("?")) + ", " +
                   std::to_string(m->value("width", 0)) + "x" +
                   std::to_string(m->value("height", 0)) + ")";
        return invalidInput(o.out + ": holds " + what +
                            " (synth-manifest.json); write to another --out, or give the same "
                            "--seed, --size, --format, --depth and --config to add to it");
    }
    return writeFileSafely(path, mine);
}

//! Linear values encoded for an 8/16-bit file by a plain power curve (the camera model's and
//! the Flare7K loaders' gamma), clipped to [0, 1].
Image encodedByGamma(const Image& linear, double gain, double gamma) {
    Image out = linear;
    for (std::size_t i = 0; i < out.pixelCount() * 4; ++i)
        out.data()[i] =
            i % 4 == 3 ? 1.f
                       : float(std::pow(std::clamp(gain * out.data()[i], 0.0, 1.0), 1.0 / gamma));
    return out;
}

Status writeEncoded(const std::string& path, const Image& image, SampleFormat format, bool srgb) {
    WriteOptions w;
    w.format = format;
    w.srgbEncode = srgb;
    return writeImage(path, image, w);
}

Status writeExr(const SynthRunOptions& o, const SynthSample& s, std::uint64_t index) {
    std::vector<NamedLayer> layers;
    for (const auto& [name, image] : s.layers) layers.push_back({name, &image});
    WriteOptions w;
    w.format = SampleFormat::Float;
    w.exrExtras = withLayerChannels(nullptr, layers);
    return writeImage((fs::path(o.out) / (sampleName(index) + ".exr")).string(),
                      *s.layer("composite"), w);
}

//! input/, gt/, flare/ and mask/: the composite and gt as the camera model left them (or
//! sRGB-encoded without one), the flare encoded as they are, the light sources' clipped core.
Status writePairs(const SynthRunOptions& o, const SynthSample& s, std::uint64_t index) {
    const SampleFormat format = o.depth == 16 ? SampleFormat::U16 : SampleFormat::U8;
    const std::string file = sampleName(index) + ".png";
    const auto at = [&](const char* dir) { return (fs::path(o.out) / dir / file).string(); };
    const bool camera = o.config.camera;
    nlohmann::json label = nlohmann::json::parse(s.label);
    const double gain = camera ? label["camera"]["gain"].get<double>() : 1.0;
    Image flare = camera ? encodedByGamma(*s.layer("flare"), gain, s.gamma) : *s.layer("flare");
    const Image& sources = *s.layer("light_source");
    Image mask(sources.width(), sources.height());
    for (std::size_t i = 0; i < mask.pixelCount(); ++i) {
        const float* p = sources.data() + 4 * i;
        const float v = luminance(p[0], p[1], p[2]) >= 1.f ? 1.f : 0.f;
        mask.data()[4 * i] = mask.data()[4 * i + 1] = mask.data()[4 * i + 2] = v;
        mask.data()[4 * i + 3] = 1;
    }
    for (const auto& [dir, image, srgb] :
         {std::tuple{"input", s.layer("composite"), !camera},
          std::tuple{"gt", s.layer("gt"), !camera},
          std::tuple{"flare", static_cast<const Image*>(&flare), !camera},
          std::tuple{"mask", static_cast<const Image*>(&mask), false}}) {
        if (Status st = writeEncoded(at(dir), *image, format, srgb); !st) return st;
    }
    return Ok{};
}

//! The Flare7K++ tree: compound (scattering) flare with its light, the light alone, and the
//! reflective ghosts, 8-bit, gamma 2.2, the light at the centre over black.
Status writeFlare7k(const SynthRunOptions& o, const SynthSample& s, std::uint64_t index) {
    constexpr double kGamma = 2.2;  // the Flare7K loaders' own decoding gamma
    const std::string file = sampleName(index) + ".png";
    const Image& sources = *s.layer("light_source");
    const Image* ghosts = s.layer("ghosts");
    Image compound = *s.layer("flare");
    for (std::size_t i = 0; i < compound.pixelCount() * 4; ++i) {
        if (i % 4 == 3) continue;
        compound.data()[i] += sources.data()[i] - (ghosts ? ghosts->data()[i] : 0.f);
        compound.data()[i] = std::max(0.f, compound.data()[i]);
    }
    Image reflective = ghosts ? *ghosts : Image(sources.width(), sources.height());
    const fs::path root(o.out);
    for (const auto& [path, image] :
         {std::pair<fs::path, const Image*>{root / "Scattering_Flare" / "Compound_Flare" / file,
                                            &compound},
          std::pair{root / "Scattering_Flare" / "Light_Source" / file, &sources},
          std::pair{root / "Reflective_Flare" / file, static_cast<const Image*>(&reflective)}}) {
        if (Status st = writeEncoded(path.string(), encodedByGamma(*image, 1.0, kGamma),
                                     SampleFormat::U8, false);
            !st)
            return st;
    }
    return Ok{};
}

Status writeSample(const SynthRunOptions& o, std::uint64_t index) {
    auto sample =
        synthSample(index, o.seed, o.width, o.height, o.config, o.format == SynthFormat::Flare7kpp);
    if (!sample) return sample.error();
    Status written = o.format == SynthFormat::Exr     ? writeExr(o, *sample, index)
                     : o.format == SynthFormat::Pairs ? writePairs(o, *sample, index)
                                                      : writeFlare7k(o, *sample, index);
    if (!written) return written;
    // The label last: its presence is what marks the sample complete.
    return writeFileSafely(labelPath(o.out, index), sample->label + "\n");
}

//! Bytes per pixel of one sample in flight: about 14 RGBA float layers (background, sources,
//! flare and its parts, gt, composite, the encodes) and the post-process chain's buffers.
constexpr double kSynthBytesPerPixel = 14 * 16 + 48;

Status checkRun(const SynthRunOptions& o) {
    if (o.count < 1 || o.count > (std::uint64_t(1) << 40))
        return invalidInput("--count: expected a whole number of samples from 1, got " +
                            std::to_string(o.count));
    if (o.width < 1 || o.height < 1 || o.width > kMaxSynthSide || o.height > kMaxSynthSide)
        return invalidInput("--size: expected WxH from 1 to " + std::to_string(kMaxSynthSide) +
                            " pixels a side, got " + std::to_string(o.width) + "x" +
                            std::to_string(o.height));
    if (o.shardCount < 1 || o.shardIndex < 0 || o.shardIndex >= o.shardCount)
        return invalidInput("--shard: expected I/K with 0 <= I < K, got " +
                            std::to_string(o.shardIndex) + "/" + std::to_string(o.shardCount));
    if (o.format == SynthFormat::Flare7kpp && o.width != o.height)
        return invalidInput("--size: the flare7kpp layout's flares are square, got " +
                            std::to_string(o.width) + "x" + std::to_string(o.height));
    if (o.depth != 8 && o.depth != 16)
        return invalidInput("--depth: expected 8 or 16, got " + std::to_string(o.depth));
    if (o.out.empty()) return invalidInput("--out: expected a folder");
    return checkSynthConfig(o.config);
}

}  // namespace

Result<SynthRunReport> runSynthJob(const SynthRunOptions& o, const JobEvents& events) {
    if (Status s = checkRun(o); !s) return s.error();
    // Backgrounds: a folder without a readable image is refused before any work.
    if (!o.config.backgrounds.empty()) {
        auto probe = synthSample(0, o.seed, 8, 8, o.config);
        if (!probe) return probe.error();
    }
    const double perSample = kSynthBytesPerPixel * double(o.width) * double(o.height);
    const int threads = std::max(1, tbb::this_task_arena::max_concurrency());
    const double budget = double(resourceLimits().maxMemoryBytes);
    if (Status s = checkMemory(
            "synth", perSample,
            "one sample at " + std::to_string(int(kSynthBytesPerPixel)) + " bytes per pixel");
        !s)
        return s.error();
    const int parallel = std::clamp(int(budget / perSample), 1, threads);
    if (Status s = claimFolder(o); !s) return s.error();

    const std::uint64_t first = o.count * std::uint64_t(o.shardIndex) / std::uint64_t(o.shardCount);
    const std::uint64_t last =
        o.count * std::uint64_t(o.shardIndex + 1) / std::uint64_t(o.shardCount);
    std::vector<std::uint64_t> todo;
    SynthRunReport report;
    for (std::uint64_t i = first; i < last; ++i) {
        std::error_code ec;
        if (o.resume && fs::exists(labelPath(o.out, i), ec))
            ++report.skipped;
        else
            todo.push_back(i);
    }
    std::mutex mutex;
    std::optional<Error> failure;
    std::atomic<std::uint64_t> done{0};
    tbb::task_arena arena(parallel);
    arena.execute([&] {
        tbb::parallel_for(std::size_t(0), todo.size(), [&](std::size_t k) {
            {
                std::lock_guard lock(mutex);
                if (failure) return;
            }
            if (events.stopRequested()) {
                std::lock_guard lock(mutex);
                if (!failure)
                    failure =
                        cancelledError("samples before it are complete (rerun with --resume)");
                return;
            }
            if (Status s = writeSample(o, todo[k]); !s) {
                std::lock_guard lock(mutex);
                if (!failure)
                    failure = Error{s.error().code,
                                    "sample " + std::to_string(todo[k]) + ": " + s.error().message};
                return;
            }
            const std::uint64_t n = ++done;
            if (events.progress) {
                std::lock_guard lock(mutex);
                events.progress(int(std::min<std::uint64_t>(n, 1u << 30)),
                                int(std::min<std::uint64_t>(todo.size(), 1u << 30)));
            }
        });
    });
    if (failure) return *failure;
    report.written = done;

    // The whole set there (this shard was the last, or the only one): labels.jsonl, in order.
    for (std::uint64_t i = 0; i < o.count; ++i) {
        std::error_code ec;
        if (!fs::exists(labelPath(o.out, i), ec)) return report;
    }
    std::string lines;
    for (std::uint64_t i = 0; i < o.count; ++i) {
        auto line = readTextFile(labelPath(o.out, i));
        if (!line) return line.error();
        lines += *line;
    }
    if (Status s = writeFileSafely((fs::path(o.out) / "labels.jsonl").string(), lines); !s)
        return s.error();
    // A writer killed outright (SIGKILL, a lost Dask worker) leaves its temporary file; with
    // every sample complete no writer of this set is needed any more, so its leftovers go.
    removeOrphanTempFiles(o.out);
    report.complete = true;
    return report;
}

}  // namespace flarekit
