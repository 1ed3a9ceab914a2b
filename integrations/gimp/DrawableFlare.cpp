// SPDX-License-Identifier: Apache-2.0
#include "DrawableFlare.h"

#include <gegl.h>

#include <cmath>
#include <string>

#include "flarekit/Limits.h"

namespace flarekit::gimp {

namespace {

//! GEGL's linear-light RGBA float: what flarekit works in (babl converts from and to the
//! image's precision and transfer curve).
const Babl* linearRgba() {
    return babl_format("RGBA float");
}

//! Integer precisions hold display-referred pixels (white is the display's); float ones hold
//! scene-linear data.
bool displayReferred(GimpPrecision p) {
    switch (p) {
        case GIMP_PRECISION_U8_LINEAR:
        case GIMP_PRECISION_U8_GAMMA:
        case GIMP_PRECISION_U16_LINEAR:
        case GIMP_PRECISION_U16_GAMMA:
        case GIMP_PRECISION_U32_LINEAR:
        case GIMP_PRECISION_U32_GAMMA:
            return true;
        default:
            return false;
    }
}

struct BufferRef {
    GeglBuffer* buffer;
    ~BufferRef() {
        if (buffer) g_object_unref(buffer);
    }
};

Status writeBuffer(GeglBuffer* buffer, const Image& image) {
    if (!buffer) return Error{ErrorCode::Internal, "GIMP gave no buffer to write"};
    const GeglRectangle rect{0, 0, image.width(), image.height()};
    gegl_buffer_set(buffer, &rect, 0, linearRgba(), image.data(), GEGL_AUTO_ROWSTRIDE);
    g_object_unref(buffer);  // flushes it to GIMP
    return Ok{};
}

}  // namespace

Result<PixelInput> readDrawable(gint32 image, gint32 drawable, double scale) {
    BufferRef ref{gimp_drawable_get_buffer(drawable)};
    if (!ref.buffer) return Error{ErrorCode::Internal, "GIMP gave no pixels for the drawable"};
    const int width = gegl_buffer_get_width(ref.buffer);
    const int height = gegl_buffer_get_height(ref.buffer);
    const int w = std::max(1, int(std::lround(width * scale)));
    const int h = std::max(1, int(std::lround(height * scale)));
    if (Status s = checkMemory("gimp", double(w) * double(h) * 16.0 * 4, "the drawable"); !s)
        return s.error();
    PixelInput input;
    input.image = Image(w, h);
    const GeglRectangle rect{0, 0, w, h};
    gegl_buffer_get(ref.buffer, &rect, scale, linearRgba(), input.image.data(), GEGL_AUTO_ROWSTRIDE,
                    GEGL_ABYSS_NONE);
    input.displayReferred = displayReferred(gimp_image_get_precision(image));
    input.hasAlpha = gimp_drawable_has_alpha(drawable);
    gchar* name = gimp_item_get_name(drawable);
    input.name = name ? name : "layer";
    g_free(name);
    return input;
}

host::FlareRequest flareRequest(const Settings& s, gint32 drawable, double scale) {
    host::FlareRequest request;
    request.intensity = float(s.intensity);
    request.threshold = s.threshold;
    if (!s.findLight) {
        gint ox = 0, oy = 0;
        gimp_drawable_offsets(drawable, &ox, &oy);
        request.light = Point{float((s.x - ox) * scale), float((s.y - oy) * scale)};
    }
    return request;
}

Status flareDrawable(gint32 image, gint32 drawable, const Settings& s, const JobEvents& events) {
    (void)events;
    auto look = host::Look::load(s.flareMode(), s.presetName());
    if (!look) return look.error();
    auto input = readDrawable(image, drawable);
    if (!input) return input.error();
    const Image plate = input->image;
    auto flared = host::drawFlare(*look, flareRequest(s, drawable), std::move(*input));
    if (!flared) return flared.error();

    gimp_image_undo_group_start(image);
    Status written = Ok{};
    if (s.newLayer) {
        // The flare alone, added in linear light above the drawable: GIMP's Addition mode
        // composites in linear RGB, so the stack shows the same image as flaring the drawable.
        Image& flare = *flared;
        float* f = flare.data();
        const float* p = plate.data();
        for (std::size_t i = 0; i < 4 * flare.pixelCount(); i += 4) {
            for (std::size_t c = 0; c < 3; ++c) f[i + c] = std::max(0.f, f[i + c] - p[i + c]);
            f[i + 3] = 1.f;
        }
        const bool gray = gimp_image_base_type(image) == GIMP_GRAY;
        const gint32 layer = gimp_layer_new(image, "flarekit flare", flare.width(), flare.height(),
                                            gray ? GIMP_GRAYA_IMAGE : GIMP_RGBA_IMAGE, 100,
                                            GIMP_LAYER_MODE_ADDITION);
        gint ox = 0, oy = 0;
        gimp_drawable_offsets(drawable, &ox, &oy);
        const gint32 parent = gimp_item_get_parent(drawable);
        if (layer < 0 || !gimp_image_insert_layer(image, layer, parent > 0 ? parent : 0,
                                                  gimp_image_get_item_position(image, drawable)))
            written = Error{ErrorCode::Internal, "GIMP refused the new layer"};
        else {
            gimp_layer_set_offsets(layer, ox, oy);
            written = writeBuffer(gimp_drawable_get_buffer(layer), flare);
            gimp_drawable_update(layer, 0, 0, flare.width(), flare.height());
        }
    } else {
        written = writeBuffer(gimp_drawable_get_shadow_buffer(drawable), *flared);
        if (written) {
            gimp_drawable_merge_shadow(drawable, TRUE);
            gimp_drawable_update(drawable, 0, 0, flared->width(), flared->height());
        }
    }
    gimp_image_undo_group_end(image);
    return written;
}

}  // namespace flarekit::gimp
