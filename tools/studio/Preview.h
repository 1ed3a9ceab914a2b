// SPDX-License-Identifier: Apache-2.0
// The studio's pictures, made on the CPU by the library's apply job (the same code the CLI
// runs, so what the studio shows is what `flarekit apply` writes): the image with its flare at
// the size the view shows it, the image without it (the before half of the split), the flare's
// passes for the component previews, and a thumbnail per element. 8-bit sRGB RGBA, ready for a
// texture; no GL here.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "Document.h"
#include "flarekit/Image.h"

namespace flarekit::studio {

struct PreviewFrame {
    Image8 after;  //!< the image with its flare, through the view's exposure and curve
    //! Each pass alone and the whole flare (renderComponents), the same way.
    std::vector<std::pair<std::string, Image8>> layers;
    double renderMs = 0;  //!< the job's wall time
};

//! The component previews' size: a strip of small pictures (the 3ds Max idea), each the whole
//! frame at this width, so that the passes cost a fraction of the view's update.
inline constexpr int kComponentWidth = 320;

class Preview {
  public:
    //! Sizes the preview to fit maxWidth x maxHeight (never above the image's own size): the
    //! image is area-averaged down once per size, so a 4096-pixel photograph costs what the
    //! screen shows. `coarse` divides that size again (a drag on a slow machine).
    void fit(const Document& doc, int maxWidth, int maxHeight, int coarse = 1);
    //! A drag's preview: a lens flare with its brightest ghosts only (Document::lensOptions).
    bool dragging = false;
    //! The flare at the fitted size.
    Result<PreviewFrame> render(const Document& doc) const;
    //! Each pass of the flare and the whole flare, kComponentWidth wide (in `layers`).
    Result<PreviewFrame> renderComponents(const Document& doc) const;
    //! The image at the fitted size through the view's exposure and curve, without a flare.
    Image8 before(const Document& doc) const;
    //! The image at kComponentWidth and its scale (pixels per image pixel): the thumbnails'.
    const PixelInput& small() const { return m_small; }
    double smallScale() const { return m_smallScale; }
    int width() const { return m_scaled.image.width(); }
    int height() const { return m_scaled.image.height(); }

  private:
    Result<PreviewFrame> renderAt(const Document& doc, const PixelInput& image, double scale,
                                  bool layers) const;
    PixelInput m_scaled, m_small;
    double m_scale = 1, m_smallScale = 1;
    unsigned m_imageVersion = 0;
    int m_fitWidth = 0, m_fitHeight = 0;
};

//! An element alone, `size` pixels square, scaled to its own peak so that a faint ghost shows
//! its shape and colour as clearly as a bright glow (a hidden element is drawn as it would be).
Image8 elementThumbnail(const ElementParams& element, int size);

//! `image` area-averaged to width x height (each output pixel the mean of the input pixels it
//! covers): no sparkle from a sun that a bilinear sample would skip.
Image downscaleArea(const Image& image, int width, int height);

//! Linear RGBA through `curve` and `exposure` to 8-bit sRGB RGBA, opaque.
Image8 toDisplay(Image image, ToneOperator curve, float exposure);

}  // namespace flarekit::studio
