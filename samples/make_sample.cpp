// SPDX-License-Identifier: Apache-2.0
// Generates the shipped sample images: a sunset over hills with trees, as an 8-bit PNG and as
// a linear HDR EXR whose sun disc has the value kHdrSunValue.
// Usage: flarekit_make_sample OUT_DIR   (writes sunset.png and sunset-hdr.exr)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "flarekit/ImageIO.h"

using namespace flarekit;

namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr float kSunX = 930.f, kSunY = 250.f, kSunRadius = 16.f;
//! The HDR sun: a core of radius 5 px at 6,400 (flux 0.97 frame heights squared, the
//! reference flux of the energy model in flarekit/Flare.h, so presets show their designed look)
//! inside the 16-pixel disc at 50. The 8-bit sample clips both to 1.
constexpr float kHdrSunValue = 6400.f, kHdrDiscValue = 50.f, kSunCoreRadius = 5.f;
//! The lens's veiling glare around the sun, kGlarePeak / (1 + (d / kSunRadius)^2): the 1/d^2
//! tail of a real lens's point spread, which clips the sky to white out to ~140 px in the
//! 8-bit sample, as a phone photo of a low sun does.
constexpr float kGlarePeak = 50.f;

float smooth(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
    return t * t * (3.f - 2.f * t);
}

float hill(float x) {  // silhouette height in pixels from the bottom
    return 150.f + 40.f * std::sin(x * 0.004f + 1.f) + 22.f * std::sin(x * 0.011f + 0.3f) +
           8.f * std::sin(x * 0.037f);
}

// Conifer silhouettes: a narrow triangle per tree, positions from a fixed list.
bool inTree(float x, float y) {
    const float trees[][3] = {{120, 90, 20},  {175, 130, 26},  {240, 70, 16},
                              {560, 110, 22}, {610, 80, 17},   {1010, 150, 28},
                              {1060, 95, 20}, {1110, 125, 24}, {1200, 85, 18}};
    for (const auto& t : trees) {
        const float base = float(kHeight) - hill(t[0]) + 6.f, top = base - t[1];
        if (y < top || y > base) continue;
        const float halfWidth = t[2] * (y - top) / (base - top);
        if (std::abs(x - t[0]) <= halfWidth) return true;
    }
    return false;
}

Image render(float sunValue) {
    Image img(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            // 4x4 supersampling keeps silhouettes and the sun's edge antialiased.
            float r = 0, g = 0, b = 0;
            for (int sy = 0; sy < 4; ++sy) {
                for (int sx = 0; sx < 4; ++sx) {
                    const float px = float(x) + (float(sx) + 0.5f) / 4.f,
                                py = float(y) + (float(sy) + 0.5f) / 4.f;
                    const float h = py / float(kHeight);
                    // Sky: deep blue overhead to orange at the horizon, brighter toward the sun.
                    float cr = 0.05f + 0.9f * smooth(0.1f, 0.8f, h),
                          cg = 0.07f + 0.35f * smooth(0.2f, 0.85f, h),
                          cb = 0.25f - 0.15f * smooth(0.3f, 0.9f, h);
                    const float ds = std::hypot(px - kSunX, py - kSunY);
                    const float glare = kGlarePeak / (1.f + (ds / kSunRadius) * (ds / kSunRadius));
                    const float halo = 0.5f * std::exp(-ds / 90.f) + glare;
                    cr += halo;
                    cg += halo * 0.7f;
                    cb += halo * 0.35f;
                    if (ds < kSunRadius) cr = cg = cb = std::min(sunValue, kHdrDiscValue);
                    if (ds < kSunCoreRadius) cr = cg = cb = sunValue;
                    if (py > float(kHeight) - hill(px) || inTree(px, py)) {
                        cr = 0.02f;
                        cg = 0.018f;
                        cb = 0.025f;
                    }
                    r += cr;
                    g += cg;
                    b += cb;
                }
            }
            img.at(x, y) = {r / 16.f, g / 16.f, b / 16.f, 1.f};
        }
    }
    return img;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
        return 2;
    }
    const std::string dir = argv[1];
    for (auto [name, sun] :
         {std::pair{"sunset.png", 1.f}, std::pair{"sunset-hdr.exr", kHdrSunValue}}) {
        if (Status s = writeImage(dir + "/" + name, render(sun)); !s) {
            std::fprintf(stderr, "%s\n", s.error().message.c_str());
            return 1;
        }
    }
    return 0;
}
