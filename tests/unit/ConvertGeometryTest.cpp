// SPDX-License-Identifier: Apache-2.0
// flarekit convert, geometry: each engine's position and size conventions checked by rendering
// the imported element and finding it where that engine's own formula puts it (a light in a
// corner, two aspect ratios); an imported look against the same elements written by hand; the
// polygon's rounded corners against their definition.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>

#include "ConvertTestSupport.h"
#include "TempDir.h"

namespace flarekit {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace test;

struct Drawn {
    double cx = 0, cy = 0;         //!< centroid of what was drawn
    double width = 0, height = 0;  //!< its extent (pixels above half the peak)
    double fullWidth = 0;          //!< its whole extent, soft edge included (above 0.1%)
};

Drawn render(const Preset& preset, int w, int h, Point light) {
    Image image(w, h);
    renderFlare(image, preset, light, 1.f);
    double sum = 0, peak = 0;
    Drawn d;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double v = image.at(x, y).g;
            peak = std::max(peak, v);
            sum += v;
            d.cx += v * (x + 0.5);
            d.cy += v * (y + 0.5);
        }
    d.cx /= sum;
    d.cy /= sum;
    int x0 = w, x1 = -1, y0 = h, y1 = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (image.at(x, y).g > 0.5 * peak) {
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
    d.width = x1 - x0 + 1;
    d.height = y1 - y0 + 1;
    int f0 = w, f1 = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (image.at(x, y).g > 1e-3 * peak) f0 = std::min(f0, x), f1 = std::max(f1, x);
    d.fullWidth = f1 - f0 + 1;
    return d;
}

Preset importSprite(const std::string& path, const ConvertOptions& options = {}) {
    auto asset = importFlare(path, options);
    EXPECT_TRUE(asset.ok()) << (asset ? "" : asset.error().message);
    return asset ? asset->sprite : Preset{};
}

// A light near the top-left corner of a 640x360 frame (clip space: x -0.9, y +0.8).
constexpr int kW = 640, kH = 360;
const Point kLight{32.f, 36.f};
double clipX(double px) {
    return 2.0 * px / kW - 1.0;
}
double clipY(double py) {
    return 1.0 - 2.0 * py / kH;
}
double pixelX(double cx) {
    return (cx + 1.0) * kW / 2.0;
}
double pixelY(double cy) {
    return (1.0 - cy) * kH / 2.0;
}
//! Where three.js's Lensflare and Unity's LensFlareCommonSRP both draw an element at `t` (their
//! distance and position): the light's clip-space position x (1 - 2t), to half a pixel.
void expectAtClipSpaceMirror(const Drawn& d, double t) {
    EXPECT_NEAR(d.cx, pixelX(clipX(kLight.x) * (1 - 2 * t)), 0.5) << t;
    EXPECT_NEAR(d.cy, pixelY(clipY(kLight.y) * (1 - 2 * t)), 0.5) << t;
}

TEST(Convert, BabylonPlacesAFlareWhereLensFlareSystemDrawsIt) {
    TempDir dir;
    ASSERT_TRUE(writeSquareTexture(dir.file("sq.png")));
    for (double position : {0.0, 0.5, -0.7}) {
        spit(dir.file("b.json"), R"({"flares":[{"size":0.05,"position":)" +
                                     std::to_string(position) +
                                     R"(,"color":[1,1,1],"textureName":"sq.png"}]})");
        const Drawn d = render(importSprite(dir.file("b.json")), kW, kH, kLight);
        // lensFlareSystem.ts: x = centerX - (centerX - lightX) * position.
        EXPECT_NEAR(d.cx, kW / 2.0 - (kW / 2.0 - kLight.x) * position, 0.5) << position;
        EXPECT_NEAR(d.cy, kH / 2.0 - (kH / 2.0 - kLight.y) * position, 0.5) << position;
    }
}

TEST(Convert, ThreeJsPlacesAnElementWhereLensflareDrawsIt) {
    TempDir dir;
    ASSERT_TRUE(writeSquareTexture(dir.file("sq.png")));
    for (double distance : {0.0, 0.25, 0.8}) {
        spit(dir.file("t.json"), R"({"elements":[{"texture":"sq.png","size":20,"distance":)" +
                                     std::to_string(distance) + "}]}");
        const Drawn d = render(importSprite(dir.file("t.json")), kW, kH, kLight);
        // Lensflare.js: positionScreen + (-2 positionScreen) x distance, in clip space.
        expectAtClipSpaceMirror(d, distance);
    }
}

TEST(Convert, UnityPlacesAnElementWhereLensFlareCommonSrpDrawsIt) {
    TempDir dir;
    for (double position : {0.0, 0.3, 0.9}) {
        spit(dir.file("u.asset"),
             unityAsset("flareType: 2\n    m_SideCount: 4\n    m_EdgeOffset: 1\n    position: " +
                        std::to_string(position) + "\n    uniformScale: 0.4"));
        const Drawn d = render(importSprite(dir.file("u.asset")), kW, kH, kLight);
        // LensFlareCommonSRP: screenPos x (1 - 2 x position) in clip space.
        expectAtClipSpaceMirror(d, position);
    }
}

TEST(Convert, PlayCanvasOffsetRunsFromTheLightThroughTheCentre) {
    TempDir dir;
    for (double offset : {0.0, 1.0, 1.6}) {
        spit(dir.file("p.json"), R"({"elements":[{"shape":"circle","size":0.05,"offset":)" +
                                     std::to_string(offset) + "}]}");
        const Drawn d = render(importSprite(dir.file("p.json")), kW, kH, kLight);
        EXPECT_NEAR(d.cx, kLight.x + (kW / 2.0 - kLight.x) * offset, 0.5) << offset;
        EXPECT_NEAR(d.cy, kLight.y + (kH / 2.0 - kLight.y) * offset, 0.5) << offset;
    }
}

TEST(Convert, SizesFollowEachEnginesScreenGeometryAtTwoAspects) {
    TempDir dir;
    ASSERT_TRUE(writeSquareTexture(dir.file("sq.png")));
    const Point centre{0, 0};
    for (int w : {640, 480}) {
        ConvertOptions options;
        options.aspect = float(w) / kH;
        options.referenceHeight = kH;
        const Point light{float(w) / 2.f, float(kH) / 2.f};
        (void)centre;
        // Babylon: a square of half side size x W / 4 pixels.
        spit(dir.file("b.json"),
             R"({"flares":[{"size":0.2,"position":1,"color":[1,1,1],"textureName":"sq.png"}]})");
        Drawn d = render(importSprite(dir.file("b.json"), options), w, kH, light);
        EXPECT_NEAR(d.width, 0.2 * w / 2.0, 1.0) << w;
        EXPECT_NEAR(d.height, 0.2 * w / 2.0, 1.0) << w;
        // three.js: `size` pixels a side at the reference height.
        spit(dir.file("t.json"), R"({"elements":[{"texture":"sq.png","size":90}]})");
        d = render(importSprite(dir.file("t.json"), options), w, kH, light);
        EXPECT_NEAR(d.width, 90, 1.0) << w;
        // Unity: 0.1 x uniformScale x sizeXY.y frame heights a side, x by sizeXY.x.
        spit(dir.file("u.asset"), unityAsset("flareType: 2\n    m_SideCount: 4\n    m_EdgeOffset: 1"
                                             "\n    rotation: 45\n    uniformScale: 2\n"
                                             "    sizeXY: {x: 1, y: 1}"));
        d = render(importSprite(dir.file("u.asset"), options), w, kH, light);
        // A square turned 45 degrees: its circumradius is the quad's half height.
        EXPECT_NEAR(d.height, 2 * 0.1 * 2 * kH / 2.0, 2.0) << w;
        // PlayCanvas: `size` is the diameter in frame heights.
        spit(dir.file("p.json"), R"({"elements":[{"shape":"circle","size":0.4,"offset":0}]})");
        d = render(importSprite(dir.file("p.json"), options), w, kH, light);
        EXPECT_NEAR(d.fullWidth, 0.4 * kH, 2.0) << w;
    }
}

TEST(Convert, AnImportedLookRendersAsTheSameElementsWrittenByHand) {
    // PlayCanvas's look.json, written by hand in flarekit's terms: t = 1 - offset, size halved,
    // each shape's element, the polygon's 3 copies spread 0.4 about offset 1.4.
    const std::string hand = R"({"elements":[
      {"type":"glow","t":1,"size":0.25,"color":[1,0.85,0.6],"inner_color":[1,0.85,0.6],"intensity":1.2},
      {"type":"ring","t":1,"size":0.15,"color":[0.5,0.4,0.9],"intensity":0.4},
      {"type":"polygon","t":-0.2,"size":0.06,"rotation":15,"color":[0.4,0.7,0.5],"intensity":0.3},
      {"type":"polygon","t":-0.4,"size":0.06,"rotation":15,"color":[0.4,0.7,0.5],"intensity":0.3},
      {"type":"polygon","t":-0.6,"size":0.06,"rotation":15,"color":[0.4,0.7,0.5],"intensity":0.3},
      {"type":"disc","t":-0.8,"size":0.1,"aspect":1.2,"color":[0.7,0.4,0.8],"inner_color":[0.7,0.4,0.8],"intensity":0.25},
      {"type":"image","t":1,"size":0.45,"aspect":4,"color":[0.8,0.9,1],"intensity":0.5,"texture":"streak.png"}]})";
    auto byHand = parsePreset(hand, kInterop + "/playcanvas/hand.json");
    ASSERT_TRUE(byHand.ok()) << byHand.error().message;
    const Preset imported = importSprite(kInterop + "/playcanvas/look.json");
    Image a(kW, kH), b(kW, kH);
    renderFlare(a, imported, kLight, 1.f);
    renderFlare(b, *byHand, kLight, 1.f);
    float worst = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            worst = std::max({worst, std::abs(a.at(x, y).r - b.at(x, y).r),
                              std::abs(a.at(x, y).g - b.at(x, y).g),
                              std::abs(a.at(x, y).b - b.at(x, y).b)});
    EXPECT_LT(worst, 1e-5f);
}

//! Coverage of a rounded polygon against its definition: inside exactly where the distance to
//! the polygon of apothem (1 - r) cos(pi/N) is under r cos(pi/N).
TEST(Convert, RoundedPolygonsAreThePolygonGrownByADisc) {
    ElementParams p = defaultElement(ElementType::Polygon);
    p.blades = 5;
    p.softness = 0.f;
    p.intensity = 1.f;
    p.color = {1, 1, 1};
    p.innerColor = Rgb{1, 1, 1};
    for (float r : {0.f, 0.3f, 1.f}) {
        p.roundness = r;
        const float radius = 100.f;
        const Image img = renderElement(p, radius);
        const double apothem = std::cos(std::numbers::pi / 5), inner = apothem * (1 - r);
        int wrong = 0, checked = 0;
        for (int y = 0; y < img.height(); y += 3)
            for (int x = 0; x < img.width(); x += 3) {
                const double px = (x + 0.5 - img.width() / 2.0) / radius,
                             py = (y + 0.5 - img.height() / 2.0) / radius;
                // Distance to the inner polygon: the largest over its edges of the distance
                // past each edge, exact off the corners; near corners, to the corner point.
                double dist = 0;
                for (int i = 0; i < 5; ++i) {
                    const double a = 2 * std::numbers::pi * i / 5;
                    const double along = px * std::cos(a) + py * std::sin(a) - inner;
                    const double across = std::abs(-px * std::sin(a) + py * std::cos(a)) -
                                          inner * std::tan(std::numbers::pi / 5);
                    if (along <= 0) continue;
                    dist = std::max(dist, across > 0 ? std::hypot(along, across) : along);
                }
                const double margin = 1.5 / radius;  // antialiasing band
                const double d = dist - apothem * r;
                if (std::abs(d) < margin) continue;
                ++checked;
                const bool inside = img.at(x, y).a > 0.5f;
                wrong += inside != (d < 0);
            }
        EXPECT_EQ(wrong, 0) << r;
        EXPECT_GT(checked, 1000);
    }
}

}  // namespace
}  // namespace flarekit
