// SPDX-License-Identifier: Apache-2.0
#include "Preview.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/Parallel.h"
#include "flarekit/Color.h"
#include "flarekit/Elements.h"
#include "flarekit/Tonemap.h"

namespace flarekit::studio {

Image downscaleArea(const Image& image, int width, int height) {
    Image out(width, height);
    const double sx = double(image.width()) / width, sy = double(image.height()) / height;
    for (int y = 0; y < height; ++y) {
        const int y0 = int(y * sy), y1 = std::max(y0 + 1, int((y + 1) * sy));
        for (int x = 0; x < width; ++x) {
            const int x0 = int(x * sx), x1 = std::max(x0 + 1, int((x + 1) * sx));
            double sum[4] = {0, 0, 0, 0};
            for (int j = y0; j < std::min(y1, image.height()); ++j) {
                const float* row = image.row(j);
                for (int i = x0; i < std::min(x1, image.width()); ++i)
                    for (int c = 0; c < 4; ++c) sum[c] += row[4 * i + c];
            }
            const double n = double(std::min(y1, image.height()) - y0) *
                             double(std::min(x1, image.width()) - x0);
            float* px = out.row(y) + 4 * x;
            for (int c = 0; c < 4; ++c) px[c] = float(sum[c] / n);
        }
    }
    return out;
}

Image8 toDisplay(Image image, ToneOperator curve, float exposure) {
    toneMapImage(image, curve, exposure);
    Image8 out{image.width(), image.height(), 4, {}};
    out.pixels.resize(image.pixelCount() * 4);
    const std::size_t rowBytes = std::size_t(image.width()) * 4;
    // Bands of 16 rows: the encode was an eighth of a drag's frame on one core.
    parallelFor(0, image.height(), 16, [&](int y0, int y1) {
        encodeSrgb8(image.row(y0), std::size_t(y1 - y0) * std::size_t(image.width()), 4,
                    out.pixels.data() + std::size_t(y0) * rowBytes);
        for (std::size_t i = std::size_t(y0) * rowBytes + 3; i < std::size_t(y1) * rowBytes; i += 4)
            out.pixels[i] = 255;
    });
    return out;
}

void Preview::fit(const Document& doc, int maxWidth, int maxHeight, int coarse) {
    if (!doc.hasImage()) return;
    const Image& full = doc.source().image;
    if (maxWidth <= 0 || maxHeight <= 0) return;
    const double k =
        std::min({1.0, double(maxWidth) / full.width(), double(maxHeight) / full.height()}) /
        std::max(1, coarse);
    const int w = std::max(1, int(std::lround(full.width() * k))),
              h = std::max(1, int(std::lround(full.height() * k)));
    if (doc.imageVersion() == m_imageVersion && w == m_fitWidth && h == m_fitHeight) return;
    m_scaled = doc.source();
    if (w != full.width() || h != full.height()) m_scaled.image = downscaleArea(full, w, h);
    m_scale = double(h) / full.height();
    if (doc.imageVersion() != m_imageVersion) {
        const int sw = std::min(kComponentWidth, full.width());
        const int sh = std::max(1, int(std::lround(double(full.height()) * sw / full.width())));
        m_small = doc.source();
        m_small.image = downscaleArea(full, sw, sh);
        m_smallScale = double(sh) / full.height();
    }
    m_imageVersion = doc.imageVersion();
    m_fitWidth = w, m_fitHeight = h;
}

Result<PreviewFrame> Preview::render(const Document& doc) const {
    return renderAt(doc, m_scaled, m_scale, false);
}

Result<PreviewFrame> Preview::renderComponents(const Document& doc) const {
    return renderAt(doc, m_small, m_smallScale, true);
}

Result<PreviewFrame> Preview::renderAt(const Document& doc, const PixelInput& image, double scale,
                                       bool layers) const {
    if (image.image.empty()) return invalidInput("no image is open");
    if (Status s = doc.prepareBackend(); !s) return s.error();
    const auto start = std::chrono::steady_clock::now();
    // Each job's image and passes, and the curve and exposure that show them: the sprite and
    // lens jobs return linear light (the view's curve is applied here, to the passes too); the
    // post-process chain applies its display curve itself (the preset's, else the view's).
    Result<PixelOutput> out = invalidInput("");
    ToneOperator curve = doc.view.curve, imageCurve = curve;
    float exposure = doc.view.exposure, imageExposure = exposure;
    if (doc.kind == FlareKind::Lens) {
        out = lensPixels(doc.lensOptions(scale, dragging && !layers), image, {}, layers);
    } else if (doc.kind == FlareKind::PostFx) {
        const PostFxJobOptions o = doc.postFxOptions(true);
        out = postFxPixels(o, image, {}, layers);
        curve = *o.tonemap, exposure = *o.exposure;
        imageCurve = ToneOperator::None, imageExposure = 1.f;
    } else {
        ApplyOptions o = doc.applyOptions(scale);
        o.exposure = 1.f, o.tonemap = ToneOperator::None;
        out = applyPixels(o, doc.renderedPreset(), image, {}, layers);
    }
    if (!out) return out.error();
    PreviewFrame frame;
    if (!layers) frame.after = toDisplay(std::move(out->image), imageCurve, imageExposure);
    for (auto& [name, pass] : out->layers)
        frame.layers.emplace_back(name, toDisplay(std::move(pass), curve, exposure));
    frame.renderMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return frame;
}

Image8 Preview::before(const Document& doc) const {
    return toDisplay(m_scaled.image, doc.view.curve, doc.view.exposure);
}

Image8 elementThumbnail(const ElementParams& element, int size) {
    ElementParams e = element;
    e.intensity = 1.f;
    // Nine tenths of the square across the element's wider axis.
    const float radius = 0.45f * float(size) / std::max(1.f, e.aspect);
    const Image sprite = renderElement(e, std::max(radius, 1.f));
    Image square(size, size);
    float peak = 0.f;
    const int left = (size - sprite.width()) / 2, top = (size - sprite.height()) / 2;
    for (int y = 0; y < size; ++y) {
        const int sy = y - top;
        if (sy < 0 || sy >= sprite.height()) continue;
        for (int x = 0; x < size; ++x) {
            const int sx = x - left;
            if (sx < 0 || sx >= sprite.width()) continue;
            const Rgba& s = sprite.at(sx, sy);
            square.at(x, y) = {s.r, s.g, s.b, 1.f};
            peak = std::max({peak, s.r, s.g, s.b});
        }
    }
    if (peak > 0.f) square.scale(1.f / peak);
    return toDisplay(std::move(square), ToneOperator::None, 1.f);
}

}  // namespace flarekit::studio
