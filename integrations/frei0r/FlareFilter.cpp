// SPDX-License-Identifier: Apache-2.0
#include "FlareFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>

#include "flarekit/Color.h"
#include "flarekit/job/PixelJob.h"

namespace flarekit::frei0r {

namespace {

std::string presetName(const FilterSettings& s) {
    if (!s.preset.empty()) return s.preset;
    switch (s.mode) {
        case FilterMode::PostFx:
            return kDefaultPostFxPreset;
        case FilterMode::Lens:
            return kDefaultFilterLens;
        case FilterMode::Sprite:
            break;
    }
    return kDefaultSpritePreset;
}

//! RGBA8888 to the working space: sRGB colour decoded exactly, straight alpha linear.
PixelInput decodeFrame(const std::uint8_t* in, int width, int height) {
    PixelInput input;
    input.image = Image(width, height);
    input.displayReferred = true;  // a video frame's white is the display's
    input.hasAlpha = false;
    input.name = "frame";
    const float* decode = srgb8DecodeTable();
    float* out = input.image.data();
    const std::size_t pixels = input.image.pixelCount();
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* p = in + 4 * i;
        out[4 * i + 0] = decode[p[0]];
        out[4 * i + 1] = decode[p[1]];
        out[4 * i + 2] = decode[p[2]];
        out[4 * i + 3] = float(p[3]) / 255.f;
        input.hasAlpha = input.hasAlpha || p[3] != 255;
    }
    return input;
}

//! The flare a job added to `plate`, times `gain`: what intensity means for the post-process
//! chain and the lens, whose jobs have no multiplier of their own (1 leaves the job's image).
void scaleFlare(Image& result, const Image& plate, float gain) {
    if (gain == 1.f) return;
    float* r = result.data();
    const float* p = plate.data();
    for (std::size_t i = 0; i < 4 * result.pixelCount(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) r[i + c] = p[i + c] + gain * (r[i + c] - p[i + c]);
}

}  // namespace

void FlareFilter::set(const FilterSettings& next) {
    const FilterSettings& now = m_settings;
    const bool look = next.mode != now.mode || next.preset != now.preset;
    if (look) m_loaded = false;
    if (look || next.light != now.light || next.threshold != now.threshold || next.fps != now.fps) {
        m_tracking.reset();
        m_lastTime.reset();
        m_frame = 0, m_step = 0;
    }
    m_settings = next;
}

void FlareFilter::report(const std::string& line) {
    if (line == m_lastReport) return;
    m_lastReport = line;
    std::fprintf(stderr, "flarekit (frei0r): %s; frame left unchanged\n", line.c_str());
}

Status FlareFilter::loadLook() {
    m_preset.reset(), m_postFx.reset(), m_lens.reset();
    const std::string name = presetName(m_settings);
    switch (m_settings.mode) {
        case FilterMode::Sprite: {
            auto preset = loadPreset(name);
            if (!preset) return preset.error();
            m_preset = std::move(*preset);
            break;
        }
        case FilterMode::PostFx: {
            auto params = loadPostFxPreset(name);
            if (!params) return params.error();
            m_postFx = std::make_shared<const PostFxParams>(std::move(*params));
            break;
        }
        case FilterMode::Lens: {
            auto lens = loadLens(name);
            if (!lens) return lens.error();
            m_lens = std::make_shared<const Lens>(std::move(*lens));
            break;
        }
    }
    m_loaded = true;
    return Ok{};
}

int FlareFilter::frameAt(double time) {
    if (m_lastTime) {
        const double dt = time - *m_lastTime;
        if (dt < 0 || !std::isfinite(dt)) {
            m_frame = 0, m_step = 0;  // a seek back: the track starts again
        } else if (dt > 0) {
            if (m_step == 0 || dt < m_step) m_step = dt;
            m_frame += std::max(1, int(std::min(std::lround(dt / m_step), 1L << 20)));
        }
    }
    m_lastTime = time;
    return m_frame;
}

Status FlareFilter::render(double time, const std::uint8_t* in, std::uint8_t* out) {
    if (!m_loaded) {
        if (Status s = loadLook(); !s) return s;
    }
    PixelInput input = decodeFrame(in, m_width, m_height);
    const std::string name = presetName(m_settings);
    const FilterSettings& s = m_settings;
    LightSearchOptions search;
    if (s.threshold > 0) search.minLuminance = float(s.threshold);
    const Point placed{float(s.x * m_width), float(s.y * m_height)};

    std::optional<TrackedLight> tracked;
    if (s.light == LightSource::Track && s.mode != FilterMode::PostFx) {
        const bool again = m_lastTime && time == *m_lastTime;  // the host asks for it again
        const int frame = frameAt(time);
        if (!again) {
            if (!m_tracking) m_tracking.emplace(search, s.fps);
            m_lastLight = m_tracking->next(frame, input.image);
        }
        tracked = m_lastLight;
        if (!tracked->found) {
            std::memcpy(out, in, std::size_t(m_width) * std::size_t(m_height) * 4);
            return Ok{};
        }
    }

    Result<PixelOutput> result = Error{};
    const Image plate = s.mode == FilterMode::Sprite ? Image{} : input.image;
    switch (s.mode) {
        case FilterMode::Sprite: {
            ApplyOptions o;
            o.preset = name;
            o.intensity = s.intensity;
            o.lightSearch = search;
            if (tracked) {
                // The tracked light's strength, as a tracked shot in `flarekit apply` has it.
                o.light = tracked->position;
                o.fluxMode = FluxMode::Fixed;
                o.intensity *= tracked->flareScale;
            } else if (s.light == LightSource::Position) {
                o.light = placed;
            }
            result = applyPixels(o, *m_preset, std::move(input));
            break;
        }
        case FilterMode::PostFx: {
            PostFxJobOptions o;
            o.preset = name;
            o.presetParams = m_postFx;
            if (s.threshold > 0) o.threshold = float(s.threshold);
            // A video frame clips its lights at white: without their highlights expanded (as
            // `flarekit postfx --expand-highlights` does) the chain's bright-pass sees no light.
            o.expandHighlights = ExpandHighlights{}.gain;
            result = postFxPixels(o, std::move(input));
            break;
        }
        case FilterMode::Lens: {
            LensJobOptions o;
            o.lens = name;
            o.lensData = m_lens;
            if (s.threshold > 0) o.threshold = s.threshold;
            if (tracked) {
                o.lightMode = LensLightMode::At, o.light = tracked->position;
            } else if (s.light == LightSource::Position) {
                o.lightMode = LensLightMode::At, o.light = placed;
            }
            result = lensPixels(o, std::move(input));
            break;
        }
    }
    if (!result) return result.error();
    Image& image = result->image;
    if (s.mode != FilterMode::Sprite) scaleFlare(image, plate, s.intensity);
    encodeSrgb8(image.data(), image.pixelCount(), 4, out);
    // The host's alpha exactly as it came (a job keeps it; its float round trip need not).
    for (std::size_t i = 0; i < image.pixelCount(); ++i) out[4 * i + 3] = in[4 * i + 3];
    return Ok{};
}

void FlareFilter::update(double time, const std::uint32_t* in, std::uint32_t* out) noexcept {
    const auto* from = reinterpret_cast<const std::uint8_t*>(in);
    auto* to = reinterpret_cast<std::uint8_t*>(out);
    const std::size_t bytes = std::size_t(m_width) * std::size_t(m_height) * 4;
    std::string why;
    try {
        Status s = render(time, from, to);
        if (s) return;
        why = s.error().message;
    } catch (const std::exception& e) {
        why = std::string("internal error: ") + e.what();
    } catch (...) {
        why = "internal error";
    }
    try {
        report(why);
    } catch (...) {
    }
    if (from != to) std::memmove(to, from, bytes);
}

}  // namespace flarekit::frei0r
