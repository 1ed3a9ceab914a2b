// SPDX-License-Identifier: Apache-2.0
// What the shot CLI tests share: a generated sequence (a disc light behind a foreground edge
// that moves across it, its covered share known per frame in closed form), a sun moving across
// the frame, and readers of coverage.csv and of written tracks.
#pragma once

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <gtest/gtest.h>
#include <half.h>

#include "Cli.h"
#include "flarekit/ImageIO.h"

namespace flarekit::test::shot {

using namespace flarekit;
namespace fs = std::filesystem;

constexpr int kW = 160, kH = 90, kFrames = 12;
constexpr double kLightX = 100.5, kLightY = 45.5, kRadius = 6;

//! Writes an EXR plate with `header`'s windows and attributes: float RGBA (`rgba`, 4 per pixel)
//! plus one float and one half channel beside it, each a full row-major data window.
inline void writeExrPlate(const std::string& path, Imf::Header header,
                          const std::vector<float>& rgba, const std::string& floatName,
                          const std::vector<float>& floats, const std::string& halfName,
                          const std::vector<half>& halves) {
    const Imath::Box2i window = header.dataWindow();
    const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
    Imf::FrameBuffer fb;
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, rgba.data() + c, window, 4 * sizeof(float),
                                             4 * sizeof(float) * w));
    }
    header.channels().insert(floatName, Imf::Channel(Imf::FLOAT));
    fb.insert(floatName, Imf::Slice::Make(Imf::FLOAT, floats.data(), window, sizeof(float),
                                          sizeof(float) * w));
    header.channels().insert(halfName, Imf::Channel(Imf::HALF));
    fb.insert(halfName,
              Imf::Slice::Make(Imf::HALF, halves.data(), window, sizeof(half), sizeof(half) * w));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(h);
}

//! The covered pixels of frame f: every column left of this one.
inline int edgeAt(int f) {
    return 88 + 2 * f;
}

inline double segmentShare(double d, double r) {
    if (d >= r) return 0;
    if (d <= -r) return 1;
    return (r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d)) / (M_PI * r * r);
}

//! frame f: dim sky, a disc of 50 (an HDR sun) at the light; its matte covers x < edgeAt(f).
inline void writeShot(const TempDir& dir, int frames = kFrames, int oddSizeFrame = 0) {
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
inline std::map<int, Row> readCoverage(const std::string& path) {
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

inline std::vector<std::string> shotArgs(const TempDir& in, const std::string& out) {
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

inline std::vector<std::string> with(std::vector<std::string> args,
                                     const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

inline std::size_t filesIn(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}
//! A sun of radius 5 px (50, an HDR sun) moving 3 px a frame to the right from (40.5, 40.5)
//! over a dim sky; on `sparkleFrame` a 2x2 glint 40 times as bright far from it.
inline void writeMovingSun(const TempDir& dir, int frames, int sparkleFrame) {
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

inline std::map<int, std::pair<double, double>> readTrack(const std::string& path) {
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

}  // namespace flarekit::test::shot
