// SPDX-License-Identifier: Apache-2.0
// Shots: frame patterns and farm ranges, light tracks (both formats, interpolation, every bad
// input), and a light disc's visibility against the closed-form area of a circular segment.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "TempDir.h"
#include "flarekit/Shot.h"
#include "flarekit/job/ShotTracking.h"

using namespace flarekit;
using flarekit::test::TempDir;

namespace {
//! The share of a disc of radius r on the far side of a line at signed distance d from its
//! centre (d > 0: the line misses the centre): the circular segment's area over the disc's.
double segmentShare(double d, double r) {
    if (d >= r) return 0;
    if (d <= -r) return 1;
    const double segment = r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d);
    return segment / (M_PI * r * r);
}

//! A matte that covers (1) every pixel left of x = edge, in its alpha.
Image edgeMatte(int w, int h, int edge) {
    Image m(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) m.at(x, y).a = x < edge ? 1.f : 0.f;
    return m;
}
}  // namespace

TEST(FramePattern, HashesAndPrintfTokensGiveTheSameNames) {
    auto hashes = parseFramePattern("dir/shot.####.exr");
    ASSERT_TRUE(hashes);
    EXPECT_EQ(hashes->prefix, "dir/shot.");
    EXPECT_EQ(hashes->suffix, ".exr");
    EXPECT_EQ(hashes->path(1001), "dir/shot.1001.exr");
    EXPECT_EQ(hashes->path(7), "dir/shot.0007.exr");
    EXPECT_EQ(hashes->path(123456), "dir/shot.123456.exr");  // padding is a minimum
    auto printfStyle = parseFramePattern("dir/shot.%04d.exr");
    ASSERT_TRUE(printfStyle);
    EXPECT_EQ(printfStyle->path(7), "dir/shot.0007.exr");
    EXPECT_EQ(parseFramePattern("f%d.png")->path(7), "f7.png");
    EXPECT_TRUE(isFramePattern("a.#.exr"));
    EXPECT_FALSE(isFramePattern("plain.exr"));
    EXPECT_FALSE(isFramePattern("100%.png"));
}

TEST(FramePattern, RefusesNoTokenOrTwo) {
    EXPECT_FALSE(parseFramePattern("shot.exr"));
    const auto two = parseFramePattern("v##/shot.####.exr");
    ASSERT_FALSE(two);
    EXPECT_NE(two.error().message.find("found 2"), std::string::npos) << two.error().message;
}

TEST(FramePattern, FramesOnDiskMatchTheExactNameOfEachFrame) {
    TempDir dir;
    for (const char* name : {"shot.0001.exr", "shot.0002.exr", "shot.01003.exr", "shot.10000.exr",
                             "shot.0004.png", "other.0005.exr", "shot.00x6.exr"})
        std::ofstream(dir.file(name)) << "x";
    auto pattern = parseFramePattern(dir.file("shot.####.exr"));
    ASSERT_TRUE(pattern);
    // 01003 is not what #### names frame 1003 (that is 1003), so it is not a frame.
    EXPECT_EQ(framesOnDisk(*pattern), (std::vector<int>{1, 2, 10000}));
}

TEST(FrameRange, FarmChunksAndSteps) {
    EXPECT_EQ(parseFrameRange("1-10:3", "--frames")->frames(), (std::vector<int>{1, 4, 7, 10}));
    EXPECT_EQ(parseFrameRange("1001-1040", "--frames")->frames().size(), 40u);
    EXPECT_EQ(parseFrameRange("17", "--frames")->frames(), (std::vector<int>{17}));
    for (const char* bad : {"10-1", "a-b", "1-5:0", "-3", "", "1-", "1-5:x", "1.5-3"}) {
        const auto r = parseFrameRange(bad, "--frames");
        ASSERT_FALSE(r) << bad;
        EXPECT_EQ(r.error().message.rfind("--frames: expected A-B[:step]", 0), 0u)
            << r.error().message;
    }
    EXPECT_EQ(describeFrames({5, 6, 7, 10, 12, 13}), "5-7, 10, 12-13");
    const auto huge = parseFrameRange("1-2000000000", "--frames");
    ASSERT_FALSE(huge);
    EXPECT_NE(huge.error().message.find("at most 1000000"), std::string::npos);
    EXPECT_TRUE(parseFrameRange("0-1999999999:2000", "--frames"));  // exactly a million
}

TEST(LightTrack, CsvKeysInterpolateLinearlyAndHoldTheEnds) {
    auto t = parseLightTrack("frame,x,y,intensity\r\n10,0,0,1\r\n20,100,50,3\r\n", "t.csv");
    ASSERT_TRUE(t) << t.error().message;
    const auto mid = t->at(15);
    EXPECT_FLOAT_EQ(mid.position.x, 50.f);
    EXPECT_FLOAT_EQ(mid.position.y, 25.f);
    EXPECT_FLOAT_EQ(mid.intensity, 2.f);
    EXPECT_FALSE(mid.held);
    EXPECT_TRUE(t->at(5).held);
    EXPECT_FLOAT_EQ(t->at(5).position.x, 0.f);
    EXPECT_TRUE(t->at(25).held);
    EXPECT_FLOAT_EQ(t->at(25).position.y, 50.f);
    EXPECT_FALSE(t->at(20).held);
}

TEST(LightTrack, JsonGivesTheSameTrackAndCsvRoundTrips) {
    const auto csv = parseLightTrack("frame,x,y\n1,10.25,20\n4,40,80.5\n", "t.csv");
    const auto json = parseLightTrack(
        R"({"keys": [{"frame": 1, "x": 10.25, "y": 20}, {"frame": 4, "x": 40, "y": 80.5}]})",
        "t.json");
    const auto array = parseLightTrack(R"([{"frame": 1, "x": 10.25, "y": 20},
                                           {"frame": 4, "x": 40, "y": 80.5}])",
                                       "t.json");
    ASSERT_TRUE(csv && json && array);
    for (double f : {0.0, 1.0, 2.0, 3.5, 9.0}) {
        EXPECT_EQ(csv->at(f).position.x, json->at(f).position.x);
        EXPECT_EQ(csv->at(f).position.y, array->at(f).position.y);
    }
    const auto again = parseLightTrack(lightTrackCsv(*csv), "again.csv");
    ASSERT_TRUE(again);
    ASSERT_EQ(again->keys.size(), 2u);
    EXPECT_EQ(again->keys[1].y, 80.5);
    EXPECT_FALSE(again->hasIntensity);
}

TEST(LightTrack, EveryBadInputNamesItsLineAndField) {
    const std::pair<const char*, const char*> cases[] = {
        {"frame,x,y\n1,0,0\n1,5,5\n", "t.csv: line 3: frame 1 does not come after frame 1"},
        {"frame,x,y\n5,0,0\n2,5,5\n", "t.csv: line 3: frame 2 does not come after frame 5"},
        {"frame,x,y\n1,nan,0\n", "t.csv: line 2: x: expected a finite number"},
        {"frame,x,y\n1,inf,0\n", "t.csv: line 2: x: expected a finite number"},
        {"frame,x,y\n1,2\n", "t.csv: line 2: expected 3 comma-separated numbers, got 2"},
        {"frame,x,y\n1,2,abc\n", "t.csv: line 2: y: expected a number, got 'abc'"},
        {"frame;x;y\n", "t.csv: line 1: expected the header frame,x,y"},
        {"frame,x,y,intensity\n1,2,3,-1\n", "t.csv: line 2: intensity: expected a number >= 0"},
        {"frame,x,y\n", "t.csv: the track has no keys"},
        {"", "t.csv: empty track"},
        {R"([{"frame": 1, "x": 2}])", "t.csv: keys[0]: missing \"y\""},
        {R"([{"frame": 1, "x": 2, "y": "3"}])", "t.csv: keys[0].y: expected a number"},
        {R"([{"frame": 1, "x": 2, "y": 3, "z": 1}])", "t.csv: keys[0]: unknown key 'z'"},
        {R"({"keys": 3})", "t.csv: keys: expected an array"},
        {R"([{"frame": 2, "x": 2, "y": 3}, {"frame": 1, "x": 2, "y": 3}])",
         "t.csv: keys[1]: frame 1 does not come after frame 2"},
    };
    for (const auto& [text, expected] : cases) {
        const auto t = parseLightTrack(text, "t.csv");
        ASSERT_FALSE(t) << text;
        EXPECT_EQ(t.error().message.rfind(expected, 0), 0u) << t.error().message;
    }
}

TEST(DiscVisibility, AnEdgeHidesTheCircularSegmentsShare) {
    const int w = 160, h = 120;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0;
    for (int i = 0; i < 200; ++i) {
        const double r = 1 + 30 * u(rng);
        const Point c{float(40 + 80 * u(rng)), float(35 + 50 * u(rng))};
        const int edge = int(c.x - r - 2 + (2 * r + 4) * u(rng));
        const Image matte = edgeMatte(w, h, edge);
        // Covered: the part of the disc left of x = edge, at distance c.x - edge from the centre.
        const double expected = 1 - segmentShare(double(c.x) - edge, r);
        const double got = discVisibility(matte, {}, c, r);
        worst = std::max(worst, std::abs(got - expected));
    }
    EXPECT_LT(worst, 0.003);
}

TEST(DiscVisibility, FullCoverNoneAndTheFramesEdge) {
    Image covered(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) covered.at(x, y).a = 1;
    EXPECT_EQ(discVisibility(covered, {}, {32, 32}, 10), 0.0);
    EXPECT_EQ(discVisibility(Image(64, 64), {}, {32, 32}, 10), 1.0);
    // Half the disc outside the frame: the half inside counts, here half covered.
    const Image half = edgeMatte(64, 64, 4);
    EXPECT_NEAR(discVisibility(half, {}, {0, 32}, 8), 1 - (segmentShare(-4, 8) - 0.5) / 0.5, 0.01);
    EXPECT_EQ(discVisibility(covered, {}, {-50, 32}, 10), 1.0);  // wholly outside
    EXPECT_EQ(discVisibility(covered, {}, {1e30f, 32}, 10), 1.0);
    EXPECT_EQ(discVisibility(covered, {}, {32, -1e30f}, 0.2), 1.0);
    // A sub-pixel light is the pixel under it.
    EXPECT_EQ(discVisibility(half, {}, {2.5f, 9.5f}, 0.2), 0.0);
    EXPECT_EQ(discVisibility(half, {}, {4.5f, 9.5f}, 0.2), 1.0);
}

TEST(DiscVisibility, DepthHidesWhereNearerThanTheLight) {
    Image depth(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) depth.at(x, y).r = x < 32 ? 5.f : 1000.f;
    Occluder near{0, 100.f};
    EXPECT_NEAR(discVisibility(depth, near, {32, 32}, 12), 0.5, 0.002);
    Occluder far{0, 2.f};  // the light in front of everything
    EXPECT_EQ(discVisibility(depth, far, {32, 32}, 12), 1.0);
}

namespace {
LightCandidate lightAt(float x, float y, double flux, float radius = 4, bool accepted = true,
                       float peak = 1000) {
    LightCandidate c;
    c.position = {x, y};
    c.flux = flux;
    c.radius = radius;
    c.peak = peak;
    c.flareScale = float(flux / 1000);
    c.accepted = accepted;
    return c;
}
}  // namespace

TEST(LightTracker, AFortyTimesSparkleElsewhereDoesNotMoveIt) {
    LightTracker tracker;
    double worst = 0;
    for (int f = 0; f < 40; ++f) {
        // The sun moves 3 px a frame; at frame 20 a glint 40x its flux appears for one frame.
        const float x = 100 + 3.f * float(f), y = 50 + float(f);
        std::vector<LightCandidate> lights{lightAt(x, y, 1000)};
        if (f == 20) lights.push_back(lightAt(20, 150, 40000, 2));
        const TrackedLight t = tracker.update(lights, f == 0 ? 0 : 1);
        ASSERT_TRUE(t.found);
        worst = std::max(worst, double(std::hypot(t.position.x - x, t.position.y - y)));
    }
    EXPECT_LT(worst, 1e-3);  // on the moving light from the start, the glint ignored
}

TEST(LightTracker, EqualHighlightsDoNotTradeTheLightAndALastingBrighterOneTakesIt) {
    LightTracker tracker;
    for (int f = 0; f < 30; ++f) {
        // Two highlights of nearly equal flux, each brighter every other frame.
        const double a = f % 2 ? 1000 : 1100, b = f % 2 ? 1150 : 1000;
        const TrackedLight t = tracker.update({lightAt(60, 60, a), lightAt(200, 60, b)}, 1);
        EXPECT_FLOAT_EQ(t.position.x, 60.f) << "frame " << f;
    }
    // A light three times as bright appears and stays: followed from its third frame on.
    for (int f = 0; f < 5; ++f) {
        const TrackedLight t = tracker.update({lightAt(60, 60, 1000), lightAt(300, 90, 3000)}, 1);
        EXPECT_FLOAT_EQ(t.position.x, f < 2 ? 60.f : 300.f) << "frame " << f;
    }
    // The followed light hidden for a frame: no light that frame, the same one after.
    EXPECT_FALSE(tracker.update({lightAt(60, 60, 1000)}, 1).found);
    const TrackedLight back = tracker.update({lightAt(60, 60, 1000), lightAt(300, 90, 3000)}, 1);
    EXPECT_TRUE(back.found);
    EXPECT_NEAR(back.position.x, 300.f, 1.0);
}

TEST(LightTracker, ASunsOwnGlowCandidatesNeverTakeItOver) {
    // The suns of blender-data's HDRIs panned across the frame: a small core (the accepted
    // light) and wide dim regions around it that the finder lists too (not accepted), centred a
    // few pixels off it, nearer where a tracker that has not yet learnt the speed predicts, and
    // in the city HDRI carrying more flux than the core.
    LightTracker sunrise, city;
    for (int f = 0; f < 12; ++f) {
        const float x = 356 - 8.f * float(f);
        const TrackedLight t = sunrise.update({lightAt(x, 133, 125000, 1.1f, true, 32740),
                                               lightAt(x + 4.5f, 134, 18000, 47, false, 6)},
                                              f == 0 ? 0 : 1);
        ASSERT_TRUE(t.found);
        EXPECT_NEAR(t.position.x, x, 1e-3) << "sunrise frame " << f;
        const float c = 394.2f - 20.f * float(f);
        const TrackedLight u = city.update(
            {lightAt(c - 35, 79, 124000, 142, false, 5), lightAt(c, 80, 104000, 1.3f, true, 31730),
             lightAt(c + 12, 81, 88700, 82, false, 12)},
            f == 0 ? 0 : 1);
        ASSERT_TRUE(u.found);
        EXPECT_NEAR(u.position.x, c, 1e-3) << "city frame " << f;
        EXPECT_EQ(u.flux, 104000) << "city frame " << f;
    }
    // Outshone for a frame (not accepted), the core is still followed by its peak.
    const TrackedLight t = city.update({lightAt(154.2f, 79, 124000, 142, false, 5),
                                        lightAt(154.2f, 80, 104000, 1.3f, false, 31730)},
                                       1);
    EXPECT_NEAR(t.position.x, 154.2f, 1e-3);
    EXPECT_EQ(t.flux, 104000);
    // Then hidden behind a building: only the glow is left, 12 px off (peak 12 against the
    // core's 31,730). The track holds its prediction and draws no flare instead of taking it.
    const TrackedLight hidden = city.update({lightAt(146.2f, 81, 88700, 82, false, 12)}, 1);
    EXPECT_FALSE(hidden.found);
    EXPECT_NEAR(hidden.position.x, 134.2f, 1e-3);
}

namespace {
//! A 96 x 64 HDR frame: a dim sky and a sun (a 3 px disc at 500) at x = 20 + 3 * frame, with a
//! second, dimmer light that appears from frame 8 (so the tracker has a choice to remember).
Image movingSun(int frame) {
    Image image(96, 64);
    image.fill({0.05f, 0.06f, 0.08f, 1});
    auto disc = [&](float cx, float cy, float value) {
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                if (std::hypot(float(x) + 0.5f - cx, float(y) + 0.5f - cy) <= 3.f)
                    image.at(x, y) = {value, value, value, 1};
    };
    disc(20.f + 3.f * float(frame), 20.f, 500.f);
    if (frame >= 8) disc(70.f, 48.f, 300.f);
    return image;
}
}  // namespace

TEST(LiveTracking, EachFrameDependsOnlyOnTheHalfSecondBeforeItAndASeekStartsAfresh) {
    EXPECT_EQ(trackerLookBack(24), 12);
    EXPECT_EQ(trackerLookBack(30), 15);
    LiveTracking whole({}, 24);
    std::vector<TrackedLight> lights;
    for (int f = 0; f <= 20; ++f) lights.push_back(whole.next(f, movingSun(f)));
    for (const TrackedLight& t : lights) ASSERT_TRUE(t.found);
    EXPECT_NEAR(lights[20].position.x, 80.f, 0.5f);
    // Frame 20 from the 12 frames before it alone: the same light, to the bit (as ShotTracking
    // gives a farm chunk that starts anywhere).
    LiveTracking chunk({}, 24);
    TrackedLight last;
    for (int f = 8; f <= 20; ++f) last = chunk.next(f, movingSun(f));
    EXPECT_EQ(last.position.x, lights[20].position.x);
    EXPECT_EQ(last.position.y, lights[20].position.y);
    EXPECT_EQ(last.flareScale, lights[20].flareScale);
    // Started a frame earlier: that frame falls out of the look-back, so the same light again.
    LiveTracking longer({}, 24);
    for (int f = 7; f <= 20; ++f) last = longer.next(f, movingSun(f));
    EXPECT_EQ(last.position.x, lights[20].position.x);
    // A seek back to frame 3: as a tracker that saw frames 0-3 only from frame 3 on.
    const TrackedLight seeked = whole.next(3, movingSun(3));
    LiveTracking fresh({}, 24);
    const TrackedLight alone = fresh.next(3, movingSun(3));
    EXPECT_EQ(seeked.position.x, alone.position.x);
    EXPECT_EQ(seeked.found, alone.found);
}
