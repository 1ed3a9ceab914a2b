// SPDX-License-Identifier: Apache-2.0
#include "Thumbnails.h"

#include "Preview.h"
#include "core/Parallel.h"
#include "flarekit/job/PixelJob.h"

namespace flarekit::studio {

ThumbnailRenderer::ThumbnailRenderer() : m_thread([this] { work(); }) {}

ThumbnailRenderer::~ThumbnailRenderer() {
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    m_thread.join();
}

void ThumbnailRenderer::request(FlareKind kind, PixelInput image, Point light, ViewSettings view,
                                std::vector<std::string> presets) {
    {
        std::lock_guard lock(m_mutex);
        ++m_generation;
        m_kind = kind;
        m_image = std::move(image);
        m_light = light;
        m_view = view;
        m_queue.assign(presets.begin(), presets.end());
        m_done.clear();
    }
    m_wake.notify_all();
}

std::vector<Thumbnail> ThumbnailRenderer::take() {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_done, {});
}

bool ThumbnailRenderer::busy() const {
    std::lock_guard lock(m_mutex);
    return m_working || !m_queue.empty();
}

unsigned ThumbnailRenderer::generation() const {
    std::lock_guard lock(m_mutex);
    return m_generation;
}

void ThumbnailRenderer::work() {
    std::unique_lock lock(m_mutex);
    for (;;) {
        m_wake.wait(lock, [&] { return m_stop || !m_queue.empty(); });
        if (m_stop) return;
        const std::string preset = m_queue.front();
        m_queue.pop_front();
        const unsigned generation = m_generation;
        const PixelInput image = m_image;  // copies: the next request may replace them
        const Point light = m_light;
        const ViewSettings view = m_view;
        const FlareKind kind = m_kind;
        m_working = true;
        lock.unlock();
        Thumbnail t{preset, {}, {}, generation};
        runOnThisThread([&] {
            if (kind == FlareKind::Lens) {
                // Each shipped lens at its own stop on the light: its 16 brightest ghosts on
                // 16-ray meshes and a 3-wavelength starburst (a thumbnail's detail, a tenth of
                // the full render's time).
                LensJobOptions o;
                o.lens = preset, o.lightMode = LensLightMode::At, o.light = light;
                o.tonemap = ToneOperator::None;
                o.render.ghosts = 16, o.render.gridSide = 16, o.render.starburstSamples = 3;
                auto out = lensPixels(o, image);
                if (out)
                    t.image = toDisplay(std::move(out->image), view.curve, view.exposure);
                else
                    t.error = out.error().message;
                return;
            }
            if (kind == FlareKind::PostFx) {
                auto params = loadPostFxPreset(preset);
                if (!params) {
                    t.error = params.error().message;
                    return;
                }
                auto out = postFxPixels(postFxDisplayOptions(*params, view, preset), image);
                if (out)
                    t.image = toDisplay(std::move(out->image), ToneOperator::None, 1.f);
                else
                    t.error = out.error().message;
                return;
            }
            ApplyOptions o;
            o.preset = preset, o.light = light, o.fluxMode = view.fluxMode;
            o.intensity = view.intensity;
            auto out = applyPixels(o, image);
            if (out)
                t.image = toDisplay(std::move(out->image), view.curve, view.exposure);
            else
                t.error = out.error().message;
        });
        lock.lock();
        m_working = false;
        if (generation == m_generation) m_done.push_back(std::move(t));
    }
}

}  // namespace flarekit::studio
