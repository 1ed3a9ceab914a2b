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

}  // namespace

void FlareFilter::set(const FilterSettings& next) {
    const FilterSettings& now = m_settings;
    const bool look = next.mode != now.mode || next.preset != now.preset;
    if (look) m_look.reset();
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
    const FilterSettings& s = m_settings;
    if (!m_look) {
        auto look = host::Look::load(s.mode, s.preset);
        if (!look) return look.error();
        m_look = std::move(*look);
    }
    PixelInput input = decodeFrame(in, m_width, m_height);
    host::FlareRequest request;
    request.intensity = s.intensity;
    request.threshold = s.threshold;
    if (s.light == LightSource::Position)
        request.light = Point{float(s.x * m_width), float(s.y * m_height)};
    if (s.light == LightSource::Track && s.mode != FilterMode::PostFx) {
        const bool again = m_lastTime && time == *m_lastTime;  // the host asks for it again
        const int frame = frameAt(time);
        if (!again) {
            if (!m_tracking) m_tracking.emplace(host::searchOptions(request), s.fps);
            m_lastLight = m_tracking->next(frame, input.image);
        }
        if (!m_lastLight.found) {
            std::memcpy(out, in, std::size_t(m_width) * std::size_t(m_height) * 4);
            return Ok{};
        }
        request.light = m_lastLight.position;
        request.lightScale = m_lastLight.flareScale;
    }
    auto image = host::drawFlare(*m_look, request, std::move(input));
    if (!image) return image.error();
    encodeSrgb8(image->data(), image->pixelCount(), 4, out);
    // The host's alpha exactly as it came (a job keeps it; its float round trip need not).
    for (std::size_t i = 0; i < image->pixelCount(); ++i) out[4 * i + 3] = in[4 * i + 3];
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
