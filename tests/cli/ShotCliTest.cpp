// Shots through the CLI: a generated sequence (a disc light behind a foreground edge that moves
// across it) whose covered share is known per frame in closed form; coverage.csv against it and
// the filter against an independent exponential smoother; frames bit-identical however the range
// is chunked; sequence frames equal to single-image calls; every bad input of a shot.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfTimeCodeAttribute.h>
#include <gtest/gtest.h>
#include <half.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "Cli.h"
#include "flarekit/ImageIO.h"

using namespace flarekit;
using namespace flarekit::test;
namespace fs = std::filesystem;

namespace {
constexpr int kW = 160, kH = 90, kFrames = 12;
constexpr double kLightX = 100.5, kLightY = 45.5, kRadius = 6;

//! The covered pixels of frame f: every column left of this one.
int edgeAt(int f) {
    return 88 + 2 * f;
}

double segmentShare(double d, double r) {
    if (d >= r) return 0;
    if (d <= -r) return 1;
    return (r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d)) / (M_PI * r * r);
}

//! frame f: dim sky, a disc of 50 (an HDR sun) at the light; its matte covers x < edgeAt(f).
void writeShot(const TempDir& dir, int frames = kFrames, int oddSizeFrame = 0) {
    for (int f = 1; f <= frames; ++f) {
        const int w = f == oddSizeFrame ? kW / 2 : kW;
        Image frame(w, kH), matte(w, kH);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < w; ++x) {
                const double d = std::hypot(x + 0.5 - kLightX, y + 0.5 - kLightY);
                const float v = d < kRadius ? 50.f : 0.05f + 0.001f * float(x);
                frame.at(x, y) = {v, v * 0.9f, v * 0.8f, 1.f};
                matte.at(x, y).a = x < edgeAt(f) ? 1.f : 0.f;
            }
        char name[64];
        std::snprintf(name, sizeof name, "in.%04d.exr", f);
        ASSERT_TRUE(writeImage(dir.file(name), frame));
        std::snprintf(name, sizeof name, "matte.%04d.exr", f);
        WriteOptions alpha;
        alpha.alpha = true;
        ASSERT_TRUE(writeImage(dir.file(name), matte, alpha));
    }
}

struct Row {
    double x, y, raw, filtered;
};
std::map<int, Row> readCoverage(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "frame,x,y,coverage,filtered_coverage");
    std::map<int, Row> rows;
    while (std::getline(in, line)) {
        int f = 0;
        Row r{};
        EXPECT_EQ(
            std::sscanf(line.c_str(), "%d,%lf,%lf,%lf,%lf", &f, &r.x, &r.y, &r.raw, &r.filtered), 5)
            << line;
        rows[f] = r;
    }
    return rows;
}

std::vector<std::string> shotArgs(const TempDir& in, const std::string& out) {
    return {"apply",
            in.file("in.####.exr"),
            "-o",
            out,
            "--light",
            "100.5,45.5",
            "--matte",
            in.file("matte.####.exr"),
            "--light-radius",
            "6"};
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

std::size_t filesIn(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}
}  // namespace

TEST(ShotCli, CoverageFollowsTheEdgeFrameByFrameAndTheFilterIsAnExponentialSmoother) {
    TempDir in, out;
    writeShot(in);
    const CliResult r = runCli(shotArgs(in, out.file("o.####.exr")));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readCoverage(out.file("coverage.csv"));
    ASSERT_EQ(rows.size(), std::size_t(kFrames));
    // Independent filter: attack 0.04 s / release 0.12 s at 24 fps from the first frame on.
    double smoothed = 0;
    for (int f = 1; f <= kFrames; ++f) {
        const Row& row = rows.at(f);
        EXPECT_DOUBLE_EQ(row.x, kLightX);
        EXPECT_DOUBLE_EQ(row.y, kLightY);
        const double expected = 1 - segmentShare(kLightX - edgeAt(f), kRadius);
        EXPECT_NEAR(row.raw, expected, 0.01) << "frame " << f;
        const double tau = row.raw > smoothed ? 0.04 : 0.12;
        smoothed =
            f == 1 ? row.raw : smoothed + (1 - std::exp(-1.0 / 24 / tau)) * (row.raw - smoothed);
        EXPECT_NEAR(row.filtered, smoothed, 1e-3) << "frame " << f;
    }
    // The edge sweeps the disc: visible at first, hidden at the end.
    EXPECT_EQ(rows.at(1).raw, 1.0);
    EXPECT_EQ(rows.at(kFrames).raw, 0.0);
    // The flare dims with it: the light a frame's flare adds over its input is in proportion
    // to the filtered coverage (the sprite flare is linear in its intensity; 0.005: the frames
    // are written as half floats, 2^-11 of each value).
    auto added = [&](int f) {
        char name[32];
        std::snprintf(name, sizeof name, "%04d.exr", f);
        auto flared = readImage(out.file(std::string("o.") + name));
        auto input = readImage(in.file(std::string("in.") + name));
        double sum = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) sum += flared->image.at(x, y).g - input->image.at(x, y).g;
        return sum;
    };
    const double full = added(1);
    EXPECT_GT(full, 10.0);
    for (int f = 2; f <= kFrames; ++f)
        EXPECT_NEAR(added(f) / full, rows.at(f).filtered, 0.005) << "frame " << f;
}

TEST(ShotCli, FramesAreBitIdenticalHoweverTheShotIsChunked) {
    TempDir in, whole, chunks;
    writeShot(in);
    ASSERT_EQ(runCli(shotArgs(in, whole.file("o.####.exr"))).exitCode, 0);
    for (const char* chunk : {"1-5", "6", "7-12:2", "8-12:2"}) {
        const CliResult r =
            runCli(with(shotArgs(in, chunks.file("o.####.exr")), {"--frames", chunk}));
        ASSERT_EQ(r.exitCode, 0) << chunk << ": " << r.err;
    }
    for (int f = 1; f <= kFrames; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "o.%04d.exr", f);
        EXPECT_EQ(slurp(whole.file(name)), slurp(chunks.file(name))) << name;
    }
    // Each chunk merged its rows into the one coverage.csv.
    EXPECT_EQ(slurp(whole.file("coverage.csv")), slurp(chunks.file("coverage.csv")));
}

TEST(ShotCli, ATrackMovesTheLightAndSequenceFramesEqualSingleImageCalls) {
    TempDir in, out;
    writeShot(in, 4);
    std::ofstream(in.file("track.csv")) << "frame,x,y,intensity\n1,20,20,1\n3,60,40,2\n";
    CliResult r = runCli({"apply", in.file("in.%04d.exr"), "-o", out.file("t.%04d.exr"),
                          "--light-track", in.file("track.csv")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("frames 4 are outside the keys"), std::string::npos) << r.err;
    // Frame 2 is halfway: the light at 40,30 with intensity 1.5, exactly as one call places it.
    r = runCli({"apply", in.file("in.0002.exr"), "-o", out.file("single.exr"), "--light", "40,30",
                "--intensity", "1.5"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(out.file("t.0002.exr")), slurp(out.file("single.exr")));
    // postfx over the sequence gives what it gives each frame alone.
    r = runCli({"postfx", in.file("in.####.exr"), "-o", out.file("p.####.exr")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"postfx", in.file("in.0003.exr"), "-o", out.file("p3.exr")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(out.file("p.0003.exr")), slurp(out.file("p3.exr")));
}

TEST(ShotCli, AMissingFrameStopsBeforeAnyWorkOrIsSkippedAndNamed) {
    TempDir in, out;
    writeShot(in, 8);
    fs::remove(in.file("in.0005.exr"));
    CliResult r =
        runCli({"postfx", in.file("in.####.exr"), "-o", out.file("o.####.exr"), "--frames", "1-8"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("frame 5 is missing"), std::string::npos) << r.err;
    EXPECT_EQ(filesIn(out.path()), 0u);
    r = runCli({"postfx", in.file("in.####.exr"), "-o", out.file("o.####.exr"), "--frames", "1-9",
                "--skip-missing"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("skipping missing frames 5, 9"), std::string::npos) << r.err;
    EXPECT_EQ(filesIn(out.path()), 7u);
}

TEST(ShotCli, AFrameOfAnotherSizeFailsNamingItAndTheFinishedFramesStayComplete) {
    TempDir in, out;
    writeShot(in, 10, 6);
    const CliResult r = runCli(shotArgs(in, out.file("o.####.exr")));
    EXPECT_EQ(r.exitCode, 2);
    // One error line (the progress lines before it are not errors).
    EXPECT_NE(r.err.find("flarekit: frame 6: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("written and complete"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("flarekit:", r.err.find("flarekit: frame 6") + 1), std::string::npos);
    EXPECT_FALSE(fs::exists(out.file("o.0006.exr")));
    for (const auto& e : fs::directory_iterator(out.path())) {
        const std::string name = e.path().filename().string();
        EXPECT_EQ(name.rfind("o.", 0), 0u) << "left behind: " << name;
        EXPECT_TRUE(readImage(e.path().string())) << name << " is not a complete image";
    }
    EXPECT_FALSE(fs::exists(out.file("coverage.csv")));
}

TEST(ShotCli, EveryBadShotInputIsOneLineAndWritesNothing) {
    TempDir in, out;
    writeShot(in, 3);
    std::ofstream(in.file("unsorted.csv")) << "frame,x,y\n3,1,1\n1,2,2\n";
    std::ofstream(in.file("nan.csv")) << "frame,x,y\n1,nan,1\n";
    Image small(8, 8);
    ASSERT_TRUE(writeImage(in.file("smallmatte.0001.exr"), small));
    ASSERT_TRUE(writeImage(in.file("smallmatte.0002.exr"), small));
    ASSERT_TRUE(writeImage(in.file("smallmatte.0003.exr"), small));
    const std::string seq = in.file("in.####.exr"), o = out.file("o.####.exr");
    const std::pair<std::vector<std::string>, std::string> cases[] = {
        {{"apply", seq, "-o", o, "--light-track", in.file("unsorted.csv")},
         "line 3: frame 1 does not come after frame 3"},
        {{"apply", seq, "-o", o, "--light-track", in.file("nan.csv")},
         "line 2: x: expected a finite number"},
        {{"apply", seq, "-o", seq}, "would overwrite its input"},
        {{"apply", seq, "-o", out.file("plain.exr")}, "the output must be one too"},
        {{"apply", seq, "-o", o, "--frames", "3-1"}, "--frames: expected A-B[:step]"},
        {{"apply", seq, "-o", o, "--light", "9,9", "--matte", in.file("smallmatte.####.exr")},
         "8x8, but the frame 1 it must match is 160x90"},
        {{"apply", in.file("in.0001.exr"), "-o", out.file("x.exr"), "--light-track",
          in.file("nan.csv")},
         "the input is one image"},
        {{"apply", in.file("in.0001.exr"), "-o", out.file("x.exr"), "--matte",
          in.file("matte.0001.exr")},
         "need the light's position"},
        {{"apply", seq, "-o", o, "--camera", in.file("nan.csv")}, "--camera needs the light"},
        {{"apply", seq, "-o", o, "--light", "1,1", "--light-track", in.file("nan.csv")},
         "give one of them"},
        {{"apply", seq, "-o", o, "--camera", in.file("nan.csv"), "--sun-dir", "0,0,0"},
         "--sun-dir: expected X,Y,Z"},
        {{"apply", seq, "-o", o, "--light", "1,1", "--depth-channel", "R"}, "needs --light-depth"},
        {{"apply", seq, "-o", o, "--light", "1,1", "--depth-channel", "Z", "--light-depth", "3"},
         "no channel 'Z' (it has: R, G, B, A)"},
        {{"postfx", in.file("nothing.####.exr"), "-o", o}, "no frame of this pattern exists"},
        {{"postfx", in.file("in.0001.exr"), "-o", out.file("x.exr"), "--frames", "1-3"},
         "is one image, not a frame pattern"},
        {{"postfx", seq, "-o", out.file("missing-dir/o.####.exr")}, "does not exist"},
    };
    for (const auto& [args, expected] : cases) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 2) << args.back();
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
        EXPECT_EQ(filesIn(out.path()), 0u) << r.err;
    }
}

TEST(ShotCli, LayersSumToTheFlareAndTheCompositeIsInputPlusFlareExactly) {
    TempDir in, out;
    writeShot(in, 2);
    const std::string layers = out.file("layers");
    CliResult r = runCli({"apply", in.file("in.0001.exr"), "-o", out.file("comp.exr"), "--depth",
                          "float", "--light", "100.5,45.5", "--layers", layers});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto input = readImage(in.file("in.0001.exr"));
    auto comp = readImage(out.file("comp.exr"));
    auto flare = readImage(layers + "/flare.exr");
    ASSERT_TRUE(input && comp && flare);
    // The passes the preset has, summed in their order, are the flare; input + flare is the
    // composite, both bit for bit.
    Image sum(kW, kH);
    int passes = 0;
    for (const char* name : {"glow", "halo", "ghosts", "streaks", "starburst"}) {
        auto layer = readImage(layers + "/" + name + ".exr");
        if (!layer) continue;
        ++passes;
        for (std::size_t i = 0; i < sum.pixelCount() * 4; ++i)
            sum.data()[i] += layer->image.data()[i];
    }
    EXPECT_GE(passes, 3);
    double flareLight = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const Rgba &f = flare->image.at(x, y), &s = sum.at(x, y), &i = input->image.at(x, y),
                       &c = comp->image.at(x, y);
            ASSERT_EQ(f.r, s.r);
            ASSERT_EQ(f.g, s.g);
            ASSERT_EQ(c.r, i.r + f.r);
            ASSERT_EQ(c.g, i.g + f.g);
            ASSERT_EQ(c.b, i.b + f.b);
            flareLight += f.g;
        }
    EXPECT_GT(flareLight, 10.0);
    // --flare-only writes that flare alone.
    r = runCli({"apply", in.file("in.0001.exr"), "-o", out.file("only.exr"), "--depth", "float",
                "--light", "100.5,45.5", "--flare-only"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto only = readImage(out.file("only.exr"));
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) ASSERT_EQ(only->image.at(x, y).g, flare->image.at(x, y).g);
    // A sequence's passes are sequences of their own.
    r = runCli({"apply", in.file("in.####.exr"), "-o", out.file("c.####.exr"), "--light",
                "100.5,45.5", "--layers", out.file("seq")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out.file("seq/flare.0002.exr")));
    EXPECT_TRUE(fs::exists(out.file("seq/glow.0001.exr")));
}

namespace {
//! A sun of radius 5 px (50, an HDR sun) moving 3 px a frame to the right from (40.5, 40.5)
//! over a dim sky; on `sparkleFrame` a 2x2 glint 40 times as bright far from it.
void writeMovingSun(const TempDir& dir, int frames, int sparkleFrame) {
    for (int f = 1; f <= frames; ++f) {
        Image frame(kW, kH);
        const double cx = 40.5 + 3 * (f - 1), cy = 40.5;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const bool sun = std::hypot(x + 0.5 - cx, y + 0.5 - cy) < 5;
                const bool glint = f == sparkleFrame && x >= 140 && x < 142 && y >= 70 && y < 72;
                const float v = glint ? 2000.f : sun ? 50.f : 0.05f;
                frame.at(x, y) = {v, v, v, 1.f};
            }
        char name[32];
        std::snprintf(name, sizeof name, "in.%04d.exr", f);
        WriteOptions f32;
        f32.format = SampleFormat::Float;
        ASSERT_TRUE(writeImage(dir.file(name), frame, f32));
    }
}

std::map<int, std::pair<double, double>> readTrack(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "frame,x,y,intensity");
    std::map<int, std::pair<double, double>> rows;
    while (std::getline(in, line)) {
        int f = 0;
        double x = 0, y = 0, i = 0;
        EXPECT_EQ(std::sscanf(line.c_str(), "%d,%lf,%lf,%lf", &f, &x, &y, &i), 4) << line;
        rows[f] = {x, y};
    }
    return rows;
}
}  // namespace

TEST(ShotCli, LightAutoFollowsTheSunPastAFortyTimesGlintAndWritesItsTrack) {
    TempDir in, out;
    writeMovingSun(in, 16, 9);
    const CliResult r = runCli({"apply", in.file("in.####.exr"), "-o", out.file("o.####.exr"),
                                "--write-track", out.file("track.csv")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto track = readTrack(out.file("track.csv"));
    ASSERT_EQ(track.size(), 16u);
    for (const auto& [f, p] : track) {
        EXPECT_NEAR(p.first, 40.5 + 3 * (f - 1), 1.0) << "frame " << f;
        EXPECT_NEAR(p.second, 40.5, 1.0) << "frame " << f;
    }
    // Fed back as a track, it places the same flares.
    const CliResult again = runCli({"apply", in.file("in.####.exr"), "-o", out.file("t.####.exr"),
                                    "--light-track", out.file("track.csv")});
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(slurp(out.file("o.0009.exr")), slurp(out.file("t.0009.exr")));
}

TEST(ShotCli, ACameraProjectsTheSunEachFrameAndNoneBehindIt) {
    TempDir in, out;
    writeShot(in, 4);
    // The camera pans from looking down -z to looking down +x; the sun stands 20 degrees up
    // toward -z, so it crosses the frame and is behind the camera by frame 4.
    std::ofstream(in.file("camera.json")) << R"({"frames": [
        {"frame": 1, "position": [0, 0, 0], "look_at": [0, 0, -1], "fov_y_deg": 50},
        {"frame": 4, "position": [0, 0, 0], "look_at": [3, 0, 1], "fov_y_deg": 50}]})";
    const double sun[3] = {0.2, 0.342, -0.9397};  // as given to --sun-dir
    CliResult r = runCli({"apply", in.file("in.####.exr"), "-o", out.file("o.####.exr"), "--camera",
                          in.file("camera.json"), "--sun-dir", "0.2,0.342,-0.9397", "--write-track",
                          out.file("track.csv"), "--guard-band", "0"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto track = readTrack(out.file("track.csv"));
    // An independent pinhole projection of each frame's camera (look_at linear between keys).
    const double n = std::hypot(sun[0], sun[1], sun[2]);
    int seen = 0;
    for (int f = 1; f <= 4; ++f) {
        const double t = (f - 1) / 3.0;
        double fw[3] = {3 * t, 0, -1 + 2 * t};
        const double fl = std::hypot(fw[0], fw[1], fw[2]);
        for (double& c : fw) c /= fl;
        const double right[3] = {-fw[2], 0, fw[0]};  // forward x (0, 1, 0)
        const double up[3] = {0, 1, 0};
        const double d[3] = {sun[0] / n, sun[1] / n, sun[2] / n};
        const double depth = d[0] * fw[0] + d[1] * fw[1] + d[2] * fw[2];
        if (depth <= 0) {
            EXPECT_EQ(track.count(f), 0u) << "frame " << f << ": the sun is behind the camera";
            continue;
        }
        const double focal = (kH / 2.0) / std::tan(25 * M_PI / 180);
        const double x = kW / 2.0 + focal * (d[0] * right[0] + d[2] * right[2]) / depth;
        const double y = kH / 2.0 - focal * (d[0] * up[0] + d[1] * up[1] + d[2] * up[2]) / depth;
        // In front: its row, wherever it projects (off the frame too, with no flare there).
        ASSERT_EQ(track.count(f), 1u) << "frame " << f;
        EXPECT_NEAR(track.at(f).first, x, 0.05 + 1e-5 * std::abs(x)) << "frame " << f;
        EXPECT_NEAR(track.at(f).second, y, 0.05 + 1e-5 * std::abs(y)) << "frame " << f;
        ++seen;
    }
    EXPECT_GE(seen, 2);
    EXPECT_LT(seen, 4);
    // A behind-the-camera frame is the input, unflared.
    auto o4 = readImage(out.file("o.0004.exr")), i4 = readImage(in.file("in.0004.exr"));
    EXPECT_EQ(o4->image.at(80, 45).g, i4->image.at(80, 45).g);
}

TEST(ShotCli, AnExrPlatesChannelsAttributesWindowsAndCompressionPassThrough) {
    TempDir dir;
    // A plate with a data window inside a larger display window, two channels past RGBA (a
    // float depth and a half matte), a timecode, a custom attribute, ZIP and float colour.
    const Imath::Box2i display({0, 0}, {99, 59}), data({10, 5}, {89, 54});
    const int w = 80, h = 50;
    std::vector<float> rgba(std::size_t(w * h * 4), 0.2f), depth(std::size_t(w * h));
    std::vector<half> matte(std::size_t(w * h));
    for (int i = 0; i < w * h; ++i) {
        depth[std::size_t(i)] = 100.f + float(i);
        matte[std::size_t(i)] = half(float(i % 7) / 7.f);
        rgba[std::size_t(i) * 4 + 3] = 1.f;
    }
    rgba[std::size_t(20 * w + 40) * 4] = 500.f;  // a light for postfx to flare
    {
        Imf::Header header(display, data, 1.f, Imath::V2f(0, 0), 1.f, Imf::INCREASING_Y,
                           Imf::ZIP_COMPRESSION);
        header.insert("timeCode", Imf::TimeCodeAttribute(Imf::TimeCode(1, 2, 3, 4)));
        header.insert("studio/shot", Imf::StringAttribute("sh010"));
        Imf::FrameBuffer fb;
        const char* names[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, rgba.data() + c, data,
                                                 4 * sizeof(float), 4 * sizeof(float) * w));
        }
        header.channels().insert("depth.Z", Imf::Channel(Imf::FLOAT));
        fb.insert("depth.Z", Imf::Slice::Make(Imf::FLOAT, depth.data(), data, sizeof(float),
                                              sizeof(float) * w));
        header.channels().insert("matte.A", Imf::Channel(Imf::HALF));
        fb.insert("matte.A",
                  Imf::Slice::Make(Imf::HALF, matte.data(), data, sizeof(half), sizeof(half) * w));
        Imf::OutputFile file(dir.file("plate.1001.exr").c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(h);
    }
    for (const char* job : {"apply", "postfx"}) {
        const std::string out = dir.file(std::string(job) + ".####.exr");
        const CliResult r =
            job == std::string("apply")
                ? runCli({job, dir.file("plate.####.exr"), "-o", out, "--light", "40.5,20.5"})
                : runCli({job, dir.file("plate.####.exr"), "-o", out});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        Imf::InputFile file(dir.file(std::string(job) + ".1001.exr").c_str());
        const Imf::Header& header = file.header();
        EXPECT_EQ(header.displayWindow(), display) << job;
        EXPECT_EQ(header.dataWindow(), data) << job;
        EXPECT_EQ(header.compression(), Imf::ZIP_COMPRESSION) << job;
        EXPECT_EQ(header.channels().findChannel("R")->type, Imf::FLOAT) << job;
        ASSERT_NE(header.findTypedAttribute<Imf::TimeCodeAttribute>("timeCode"), nullptr) << job;
        EXPECT_EQ(header.typedAttribute<Imf::TimeCodeAttribute>("timeCode").value().frame(), 4);
        ASSERT_NE(header.findTypedAttribute<Imf::StringAttribute>("studio/shot"), nullptr) << job;
        EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("studio/shot").value(), "sh010");
        ASSERT_NE(header.channels().findChannel("depth.Z"), nullptr) << job;
        EXPECT_EQ(header.channels().findChannel("matte.A")->type, Imf::HALF) << job;
        std::vector<float> z(std::size_t(w * h));
        std::vector<half> m(std::size_t(w * h));
        std::vector<float> red(std::size_t(w * h));
        Imf::FrameBuffer fb;
        fb.insert("depth.Z",
                  Imf::Slice::Make(Imf::FLOAT, z.data(), data, sizeof(float), sizeof(float) * w));
        fb.insert("matte.A",
                  Imf::Slice::Make(Imf::HALF, m.data(), data, sizeof(half), sizeof(half) * w));
        fb.insert("R",
                  Imf::Slice::Make(Imf::FLOAT, red.data(), data, sizeof(float), sizeof(float) * w));
        file.setFrameBuffer(fb);
        file.readPixels(data.min.y, data.max.y);
        EXPECT_EQ(z, depth) << job;
        for (std::size_t i = 0; i < m.size(); ++i) ASSERT_EQ(float(m[i]), float(matte[i])) << job;
        double added = 0;
        for (std::size_t i = 0; i < red.size(); ++i) added += red[i] - rgba[i * 4];
        EXPECT_GT(added, 1.0) << job << ": the flare is in the colour channels";
    }
    // A chosen compression overrides the plate's.
    const CliResult r = runCli({"postfx", dir.file("plate.1001.exr"), "-o", dir.file("piz.exr"),
                                "--exr-compression", "piz"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(Imf::InputFile(dir.file("piz.exr").c_str()).header().compression(),
              Imf::PIZ_COMPRESSION);
}

TEST(ShotCli, LensRenderTakesASequenceAndItsFramesEqualOneImageCalls) {
    TempDir in, out;
    writeShot(in, 3);
    CliResult r = runCli({"lens", "render", "asahi-takumar-50", in.file("in.####.exr"), "-o",
                          out.file("l.####.exr"), "--light", "100.5,45.5", "--ghosts", "4",
                          "--layers", out.file("layers")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli({"lens", "render", "asahi-takumar-50", in.file("in.0002.exr"), "-o",
                out.file("single.exr"), "--light", "100.5,45.5", "--ghosts", "4"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(out.file("l.0002.exr")), slurp(out.file("single.exr")));
    EXPECT_TRUE(fs::exists(out.file("layers/ghosts.0003.exr")));
    EXPECT_TRUE(fs::exists(out.file("layers/flare.0001.exr")));
}

TEST(ShotCli, ThePlatesOwnDepthAndMatteChannelsHideTheLightByName) {
    // Frames whose EXR carries a depth (Z: 5 on the foreground left of the edge, 1000 behind)
    // and a foreground matte (fg.A) beside the colour; the light at depth 100.
    TempDir dir;
    constexpr int frames = 6;
    for (int f = 1; f <= frames; ++f) {
        const Imath::Box2i window({0, 0}, {kW - 1, kH - 1});
        std::vector<float> rgba(std::size_t(kW * kH * 4), 0.1f), z(std::size_t(kW * kH));
        std::vector<half> fg(std::size_t(kW * kH));
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const std::size_t i = std::size_t(y * kW + x);
                const bool front = x < 88 + 4 * f;
                z[i] = front ? 5.f : 1000.f;
                fg[i] = half(front ? 1.f : 0.f);
            }
        Imf::Header header(kW, kH);
        Imf::FrameBuffer fb;
        const char* names[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, rgba.data() + c, window,
                                                 4 * sizeof(float), 4 * sizeof(float) * kW));
        }
        header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
        fb.insert(
            "Z", Imf::Slice::Make(Imf::FLOAT, z.data(), window, sizeof(float), sizeof(float) * kW));
        header.channels().insert("fg.A", Imf::Channel(Imf::HALF));
        fb.insert("fg.A",
                  Imf::Slice::Make(Imf::HALF, fg.data(), window, sizeof(half), sizeof(half) * kW));
        char name[32];
        std::snprintf(name, sizeof name, "in.%04d.exr", f);
        Imf::OutputFile file(dir.file(name).c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(kH);
    }
    for (const std::vector<std::string>& how :
         {std::vector<std::string>{"--depth-channel", "Z", "--light-depth", "100"},
          std::vector<std::string>{"--matte-channel", "fg.A"}}) {
        TempDir out;
        const CliResult r =
            runCli(with({"apply", dir.file("in.####.exr"), "-o", out.file("o.####.exr"), "--light",
                         "100.5,45.5", "--light-radius", "6"},
                        how));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto rows = readCoverage(out.file("coverage.csv"));
        ASSERT_EQ(rows.size(), std::size_t(frames));
        for (int f = 1; f <= frames; ++f)
            EXPECT_NEAR(rows.at(f).raw, 1 - segmentShare(kLightX - (88 + 4 * f), kRadius), 0.01)
                << how[0] << " frame " << f;
        // The depth and the matte pass through to the output.
        Imf::InputFile o(out.file("o.0001.exr").c_str());
        EXPECT_NE(o.header().channels().findChannel("Z"), nullptr);
        EXPECT_NE(o.header().channels().findChannel("fg.A"), nullptr);
    }
}

TEST(ShotCli, AnExrsExtraChannelsCountInTheMemoryBudget) {
    // 512x512 with 64 float channels past RGBA: 64 MiB kept for the write. Under a 200 MiB
    // budget apply's own ~175 MiB fits, with the channels it does not: refused from the header.
    TempDir dir;
    const int w = 512, h = 512;
    std::vector<float> zeros(std::size_t(w * h), 0.f);
    Imf::Header header(w, h);
    Imf::FrameBuffer fb;
    for (int c = 0; c < 68; ++c) {
        const std::string name =
            c < 4 ? std::string(1, "RGBA"[c]) : std::string("c").append(std::to_string(c));
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(zeros.data()), sizeof(float),
                                   sizeof(float) * w));
    }
    {
        Imf::OutputFile file(dir.file("wide.exr").c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(h);
    }
    const CliResult r = runCli({"--max-memory", "200M", "apply", dir.file("wide.exr"), "-o",
                                dir.file("out.exr"), "--light", "9,9"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("over the memory budget"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("out.exr")));
    EXPECT_EQ(runCli({"--max-memory", "300M", "apply", dir.file("wide.exr"), "-o",
                      dir.file("out.exr"), "--light", "9,9"})
                  .exitCode,
              0);
}
