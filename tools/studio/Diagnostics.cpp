// SPDX-License-Identifier: Apache-2.0
#include "Diagnostics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/SafeWrite.h"
#include "flarekit/Demo.h"
#include "flarekit/ImageIO.h"

namespace flarekit::studio {

namespace {

Image8 opaqueRgba(const Image8& image) {
    Image8 out{image.width, image.height, 4, {}};
    out.pixels.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
    for (std::size_t p = 0; p < std::size_t(image.width) * std::size_t(image.height); ++p) {
        for (int c = 0; c < 3; ++c)
            out.pixels[4 * p + std::size_t(c)] =
                image.pixels[p * std::size_t(image.channels) +
                             std::size_t(std::min(c, image.channels - 1))];
        out.pixels[4 * p + 3] = 255;
    }
    return out;
}

std::string fileStem(std::string name) {
    std::replace(name.begin(), name.end(), ' ', '-');
    return name;
}

}  // namespace

DiagnosticPicture methodPicture(const MethodView& view) {
    const Image& im = view.image;
    float peak = 0.f;
    for (std::size_t i = 0; i < im.pixelCount(); ++i)
        for (std::size_t c = 0; c < 3; ++c) peak = std::max(peak, im.data()[4 * i + c]);
    const float gain = peak > 0.f ? 1.f / peak : 1.f;
    Image8 out{im.width(), im.height(), 4, {}};
    out.pixels.resize(im.pixelCount() * 4);
    for (std::size_t i = 0; i < im.pixelCount(); ++i)
        for (std::size_t c = 0; c < 4; ++c)
            out.pixels[4 * i + c] =
                c == 3 ? 255
                       : std::uint8_t(
                             std::lround(std::clamp(im.data()[4 * i + c] * gain, 0.f, 1.f) * 255));
    return {view.name, std::move(out)};
}

Result<PspDiagnostics> pspDiagnosticsAt(double seconds) {
    // The drive's camera at `seconds` (DemoAnimation: t = time / duration, held at the end).
    auto input = psp::pspDemoInput(std::clamp(seconds / kDemoDurationSeconds, 0.0, 1.0));
    if (!input) return input.error();
    input->keepSteps = true;
    auto result = psp::runPspFrame(psp::PspTrick::Burnout, *input);
    if (!result) return result.error();
    PspDiagnostics out{std::move(*input), std::move(*result), {}};
    for (const psp::PspStep& step : out.result.steps)
        out.pictures.push_back({step.name, opaqueRgba(step.image)});
    return out;
}

Status writeDiagnostics(const std::string& dir, const std::vector<DiagnosticPicture>& method,
                        const PspDiagnostics& psp) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return invalidInput(dir + ": cannot make the folder (" + ec.message() + ")");
    for (const DiagnosticPicture& p : method)
        if (Status s = writeImage8(dir + "/method-" + fileStem(p.name) + ".png", p.image); !s)
            return s;
    for (const DiagnosticPicture& p : psp.pictures)
        if (Status s = writeImage8(dir + "/psp-" + fileStem(p.name) + ".png", p.image); !s)
            return s;
    Image8 mask{psp::kScreenWidth, psp::kScreenHeight, 1, {}};
    mask.pixels.resize(psp.input.occluders.size());
    for (std::size_t i = 0; i < mask.pixels.size(); ++i)
        mask.pixels[i] = psp.input.occluders[i] ? 255 : 0;
    if (Status s = writeImage8(dir + "/psp-occluders.png", mask); !s) return s;
    char text[200];
    std::snprintf(text, sizeof text,
                  "sun %d %d\nsun_in_frame %d\ncoverage_byte %d\nclut_alpha %d\nvisible %d of %d\n",
                  psp.input.sunX, psp.input.sunY, int(psp.result.sunInFrame),
                  psp.result.coverageByte, psp.result.clutAlpha, psp.result.visiblePixels,
                  psp.result.maskPixels);
    return writeFileSafely(dir + "/psp.txt", text);
}

PspDiagnosticsWorker::~PspDiagnosticsWorker() {
    if (m_running.valid()) m_running.wait();
}

void PspDiagnosticsWorker::request(int frame, double seconds) {
    if ((m_latest && m_latest->first == frame) || (m_running.valid() && m_runningFrame == frame)) {
        m_queued.reset();
        return;
    }
    m_queued = {frame, seconds};
    latest();  // starts it now when nothing runs
}

const std::optional<std::pair<int, Result<PspDiagnostics>>>& PspDiagnosticsWorker::latest() {
    using namespace std::chrono_literals;
    if (m_running.valid() && m_running.wait_for(0s) == std::future_status::ready)
        m_latest.emplace(m_runningFrame, m_running.get());
    if (!m_running.valid() && m_queued) {
        const auto [frame, seconds] = *std::exchange(m_queued, std::nullopt);
        m_runningFrame = frame;
        m_running = std::async(std::launch::async, [seconds] { return pspDiagnosticsAt(seconds); });
    }
    return m_latest;
}

}  // namespace flarekit::studio
