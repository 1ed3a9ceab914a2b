// SPDX-License-Identifier: Apache-2.0
#include "engine/FlareSet.h"

#include <cmath>

#include "engine/EngineInput.h"

namespace flarekit::engine {

namespace {
//! The tallest frame sprites are made for: the height limit of a 16K frame.
constexpr int kMaxFrameHeight = 16384;
}  // namespace

Result<int> FlareSet::loadPreset(const std::string& nameOrPath) {
    auto preset = flarekit::loadPreset(nameOrPath);
    if (!preset) return preset.error();
    m_presets.push_back({std::move(*preset), {}});
    m_height = 0;
    return int(m_presets.size()) - 1;
}

Result<int> FlareSet::loadPresetJson(const char* json, std::size_t length) {
    if (!json) return invalidInput("json: expected preset JSON text, got NULL");
    auto preset = parsePreset(std::string(json, length), "json");
    if (!preset) return preset.error();
    m_presets.push_back({std::move(*preset), {}});
    m_height = 0;
    return int(m_presets.size()) - 1;
}

Result<int> FlareSet::prepare(int height) {
    if (height < 1 || height > kMaxFrameHeight) {
        return invalidInput("frame_height: expected 1.." + std::to_string(kMaxFrameHeight) +
                            " pixels, got " + std::to_string(height));
    }
    std::vector<SpriteImage> slots;
    for (Loaded& p : m_presets) {
        std::vector<SpriteImage> images = renderSpriteImages(p.preset, height);
        p.sprites.clear();
        for (std::size_t e = 0; e < images.size(); ++e) {
            const SpriteImage& s = images[e];
            p.sprites.push_back({s, int(slots.size()), int(e)});
            slots.push_back(std::move(images[e]));
        }
    }
    m_slots = std::move(slots);
    m_height = height;
    return int(m_slots.size());
}

const SpriteImage* FlareSet::sprite(int slot) const {
    return slot >= 0 && slot < int(m_slots.size()) ? &m_slots[std::size_t(slot)] : nullptr;
}

Status FlareSet::instances(const fk_frame* frame, const fk_light* lights, const float* coverage,
                           int count, float edgeFade, std::vector<fk_flare_instance>& out) const {
    if (Status s = checkFrameNumbers(frame, "frame"); !s) return s;
    if (Status s = checkLights(lights, count, FK_MAX_LIGHTS, int(m_presets.size())); !s) return s;
    if (count > 0 && !coverage)
        return invalidInput("coverage: expected an array of count floats, got NULL");
    for (int i = 0; i < count; ++i) {
        if (!(coverage[i] >= 0.f && coverage[i] <= 1.f)) {
            return invalidInput("coverage[" + std::to_string(i) + "]: expected 0..1, got " +
                                std::to_string(coverage[i]));
        }
    }
    if (!(edgeFade >= 0.f && edgeFade <= 0.5f)) {
        return invalidInput("edge_fade: expected 0..0.5 shorter sides of the viewport, got " +
                            std::to_string(edgeFade));
    }
    if (m_height != frame->viewport[3]) {
        return invalidInput(
            m_height == 0
                ? std::string("fk_flare_set_prepare: expected a call after the last "
                              "preset was loaded")
                : "frame.viewport: expected the prepared height " + std::to_string(m_height) +
                      ", got " + std::to_string(frame->viewport[3]) +
                      " (fk_flare_set_prepare again for it)");
    }
    out.clear();
    for (std::size_t id = 0; id < m_presets.size(); ++id)
        appendFlareInstances(*frame, lights, coverage, count, int(id), m_presets[id].sprites,
                             edgeFade, out);
    return Ok{};
}

}  // namespace flarekit::engine
