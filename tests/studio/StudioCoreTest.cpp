// SPDX-License-Identifier: Apache-2.0
// The studio's model without a window: undo and redo, the preview's downscale and its parity
// with the apply job, the browser's background thumbnails, and the script's checks.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "Document.h"
#include "Preview.h"
#include "Script.h"
#include "TempDir.h"
#include "Thumbnails.h"
#include "flarekit/job/PixelJob.h"

using namespace flarekit;
using namespace flarekit::studio;
using flarekit::test::TempDir;

namespace {

const std::string kSunset = FLAREKIT_SAMPLES "/sunset.png";

ParamValue number(double v) {
    ParamValue p;
    p.number = v;
    return p;
}

}  // namespace

TEST(StudioDocument, EveryEditIsOneUndoStepAndRedoReplaysIt) {
    Document doc;
    const std::string original = presetToJson(doc.preset());
    ASSERT_TRUE(doc.setElementParam(0, "size", number(0.4)).ok());
    ASSERT_TRUE(doc.setElementParam(0, "size", number(0.45)).ok());  // one gesture: one step
    doc.commit();
    doc.setVisible(2, false);
    doc.duplicateElement(1);
    const std::string edited = presetToJson(doc.preset());
    EXPECT_TRUE(doc.isDirty());
    ASSERT_TRUE(doc.undo());  // the duplicate
    ASSERT_TRUE(doc.undo());  // the visibility
    EXPECT_TRUE(doc.preset().elements[2].visible);
    EXPECT_FLOAT_EQ(doc.preset().elements[0].size, 0.45f);
    ASSERT_TRUE(doc.undo());  // both sizes at once
    EXPECT_EQ(presetToJson(doc.preset()), original);
    EXPECT_FALSE(doc.isDirty());
    EXPECT_FALSE(doc.undo());
    while (doc.redo()) {
    }
    EXPECT_EQ(presetToJson(doc.preset()), edited);
    // A new edit after an undo drops what could have been redone.
    ASSERT_TRUE(doc.undo());
    doc.removeElement(0);
    EXPECT_FALSE(doc.canRedo());
}

TEST(StudioDocument, ThePresetKeepsAnElementAndRefusesUnknownKeys) {
    Document doc;
    while (doc.preset().elements.size() > 1) doc.removeElement(0);
    doc.removeElement(0);
    EXPECT_EQ(doc.preset().elements.size(), 1u);
    const Status s = doc.setElementParam(0, "blades", number(7));  // a glow has no blades
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message, "elements[0].blades: unknown parameter");
    EXPECT_FALSE(doc.setElementParam(5, "size", number(0.1)).ok());
}

TEST(StudioPreview, DownscaleIsTheMeanOfTheCoveredPixels) {
    Image image(4, 2);
    for (int x = 0; x < 4; ++x) {
        image.at(x, 0) = {float(x), 0.f, 1.f, 1.f};
        image.at(x, 1) = {float(x) + 4, 0.f, 1.f, 1.f};
    }
    const Image half = downscaleArea(image, 2, 1);
    EXPECT_FLOAT_EQ(half.at(0, 0).r, (0 + 1 + 4 + 5) / 4.f);
    EXPECT_FLOAT_EQ(half.at(1, 0).r, (2 + 3 + 6 + 7) / 4.f);
    EXPECT_FLOAT_EQ(half.at(1, 0).b, 1.f);
}

TEST(StudioPreview, AtFullSizeTheViewIsTheApplyJobsImage) {
    Document doc;
    ASSERT_TRUE(doc.openImage(kSunset).ok());
    doc.light = {400.5f, 300.25f};
    Preview preview;
    preview.fit(doc, 4000, 4000);
    ASSERT_EQ(preview.width(), 1280);
    auto frame = preview.render(doc);
    ASSERT_TRUE(frame.ok()) << frame.error().message;
    ApplyOptions o;
    o.light = doc.light, o.fluxMode = FluxMode::Fixed;
    auto direct = applyPixels(o, doc.source());
    ASSERT_TRUE(direct.ok());
    const Image8 expected = toDisplay(std::move(direct->image), ToneOperator::None, 1.f);
    EXPECT_EQ(frame->after.pixels, expected.pixels);
}

TEST(StudioThumbnails, EachIsThePresetOnTheImageAndStaleOnesAreDropped) {
    Document doc;
    ASSERT_TRUE(doc.openImage(kSunset).ok());
    Preview preview;
    preview.fit(doc, 800, 450);
    const Point light{200.f, 60.f};
    ThumbnailRenderer browser;
    // The first request is replaced at once: nothing of it may arrive after the second.
    browser.request(FlareKind::Sprite, preview.small(), {10.f, 10.f}, doc.view,
                    {"sun-wide", "starburst"});
    browser.request(FlareKind::Sprite, preview.small(), light, doc.view,
                    {"subtle", "hexagon-ghosts"});
    const unsigned generation = browser.generation();
    std::vector<Thumbnail> got;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while ((browser.busy() || got.size() < 2) && std::chrono::steady_clock::now() < deadline) {
        for (Thumbnail& t : browser.take()) got.push_back(std::move(t));
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    for (Thumbnail& t : browser.take()) got.push_back(std::move(t));
    ASSERT_EQ(got.size(), 2u);
    for (const Thumbnail& t : got) {
        EXPECT_EQ(t.generation, generation);
        ASSERT_TRUE(t.error.empty()) << t.error;
        ApplyOptions o;
        o.preset = t.preset, o.light = light, o.fluxMode = FluxMode::Fixed;
        auto direct = applyPixels(o, preview.small());
        ASSERT_TRUE(direct.ok());
        EXPECT_EQ(t.image.pixels,
                  toDisplay(std::move(direct->image), ToneOperator::None, 1.f).pixels)
            << t.preset;
    }
}

TEST(StudioScript, EveryActionIsCheckedBeforeTheWindowOpens) {
    TempDir dir;
    const auto load = [&](const std::string& text) {
        std::ofstream(dir.file("s.json")) << text;
        return loadScript(dir.file("s.json"));
    };
    EXPECT_TRUE(load(R"({"actions": [{"action": "undo"}, {"action": "drag", "from": [1, 2],
                        "to": [3, 4]}]})")
                    .ok());
    auto bad = load(R"({"actions": [{"action": "undo"}, {"action": "set", "value": 1}]})");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message,
              dir.file("s.json") + ": actions[1]: key: missing (\"set\" needs it)");
    bad = load(R"({"actions": [{"action": "undo", "extra": 1}]})");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("actions[0]: extra: not a field of \"undo\""),
              std::string::npos);
    bad = load(R"([1, 2])");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("expected an object {\"actions\": [...]}"),
              std::string::npos);
}

TEST(StudioDocument, OpensAndSavesOtherEnginesFlaresThroughTheConverter) {
    TempDir dir;
    Document doc;
    doc.kind = FlareKind::PostFx;
    // A Unity asset switches to sprite flares: its elements, with what did not map as warnings.
    ASSERT_TRUE(doc.loadPreset(FLAREKIT_INTEROP "/unity/Assets/Flares/SunFlare.asset").ok());
    EXPECT_EQ(doc.kind, FlareKind::Sprite);
    auto direct = importFlare(FLAREKIT_INTEROP "/unity/Assets/Flares/SunFlare.asset");
    ASSERT_TRUE(direct.ok());
    EXPECT_EQ(presetToJson(doc.preset()), presetToJson(direct->sprite));
    EXPECT_EQ(doc.warnings, direct->warnings);
    EXPECT_FALSE(doc.isDirty());
    // Edited and saved as a Unity asset: what the converter writes for the edited preset.
    ASSERT_TRUE(doc.setElementParam(0, "intensity", number(2.5)).ok());
    ASSERT_TRUE(doc.savePreset(dir.file("Edited.asset")).ok());
    EXPECT_FALSE(doc.isDirty());
    auto back = importFlare(dir.file("Edited.asset"));
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_FLOAT_EQ(back->sprite.elements[0].intensity, 2.5f);
    EXPECT_TRUE(std::filesystem::exists(dir.file("Ghost.png.meta")));
    // A Godot scene is a post-process preset; saved back as a scene beside a JSON copy.
    ASSERT_TRUE(doc.loadPreset(FLAREKIT_INTEROP "/godot/lens_flare.tscn").ok());
    EXPECT_EQ(doc.kind, FlareKind::PostFx);
    ASSERT_TRUE(doc.savePreset(dir.file("flare.tscn")).ok());
    ASSERT_TRUE(doc.savePreset(dir.file("flare.json")).ok());
    auto scene = importFlare(dir.file("flare.tscn")), preset = importFlare(dir.file("flare.json"));
    ASSERT_TRUE(scene.ok() && preset.ok());
    EXPECT_TRUE(preset->postFx);
    EXPECT_EQ(scene->chain.ghosts.size(), preset->chain.ghosts.size());
}
