// SPDX-License-Identifier: Apache-2.0
// Image files through the CLI's codecs, the sRGB transfer both ways, and the exact 8-bit blends.
#include <cmath>

#include "Bindings.h"
#include "Convert.h"
#include "flarekit/Blend.h"
#include "flarekit/Color.h"
#include "flarekit/ImageIO.h"
#include "flarekit/job/Job.h"

namespace flarekit::python {

namespace {

SampleFormat depthNamed(const std::string& name) {
    for (std::size_t i = 0; i < std::size(kSampleFormatNames); ++i)
        if (kSampleFormatNames[i] == name) return SampleFormat(i);
    std::string names;
    for (std::string_view n : kSampleFormatNames)
        names += (names.empty() ? "" : ", ") + std::string(n);
    throw py::value_error("depth: expected one of " + names + ", got '" + name + "'");
}

//! A uint8 H x W x C array (C 1-4) as an Image8, any strides.
Image8 image8FromArray(const py::handle& object, const char* what) {
    if (!py::isinstance<py::array>(object))
        throw py::value_error(std::string(what) + ": expected a numpy uint8 array");
    const py::array a = py::reinterpret_borrow<py::array>(object);
    if (!a.dtype().is(py::dtype::of<std::uint8_t>()))
        throw py::value_error(std::string(what) + ": expected uint8 samples, got " +
                              std::string(py::str(a.dtype())));
    if (a.ndim() != 3 || a.shape(2) < 1 || a.shape(2) > 4 || a.shape(0) == 0 || a.shape(1) == 0)
        throw py::value_error(std::string(what) +
                              ": expected shape H x W x C (C 1 to 4, H and W above 0)");
    if (a.shape(0) > kMaxImageSide || a.shape(1) > kMaxImageSide)
        throw py::value_error(std::string(what) + ": larger than " + std::to_string(kMaxImageSide) +
                              " pixels a side");
    Image8 out;
    out.height = int(a.shape(0)), out.width = int(a.shape(1)), out.channels = int(a.shape(2));
    out.pixels.resize(std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels));
    const auto* base = static_cast<const char*>(a.data());
    std::size_t i = 0;
    for (py::ssize_t y = 0; y < a.shape(0); ++y)
        for (py::ssize_t x = 0; x < a.shape(1); ++x)
            for (py::ssize_t c = 0; c < a.shape(2); ++c)
                out.pixels[i++] =
                    std::uint8_t(*(base + y * a.strides(0) + x * a.strides(1) + c * a.strides(2)));
    return out;
}

}  // namespace

void addImages(py::module_& m) {
    m.def(
        "read_image",
        [](const std::string& path, const std::string& part) {
            Result<LoadedImage> loaded = internalError("not run");
            CollectedEvents events;
            {
                py::gil_scoped_release release;
                loaded = readJobInput(path, {}, events.events(), {part});
            }
            events.emit();
            LoadedImage image = unwrap(std::move(loaded));
            py::dict info;
            info["display_referred"] = !image.wasFloat;
            info["has_alpha"] = image.hasAlpha;
            info["file_channels"] = image.fileChannels;
            info["half"] = image.halfExact;
            py::list parts;
            for (const std::string& p : image.exrParts) parts.append(p);
            info["parts"] = parts;
            const int channels = image.hasAlpha ? 4 : 3;
            return py::make_tuple(arrayFromImage(std::move(image.image), channels), info);
        },
        py::arg("path"), py::arg("part") = "",
        "read_image(path, part='') -> (ndarray, dict)\n\nAn image through the CLI's codecs as "
        "linear float32 H x W x 3 (x 4 with alpha): 8/16-bit files sRGB-decoded, EXR/HDR as "
        "stored. The dict: display_referred (an 8/16-bit file), has_alpha, file_channels, half, "
        "parts (a multi-part EXR's).");
    m.def(
        "write_image",
        [](const std::string& path, const py::handle& array, const std::string& depth) {
            bool hasAlpha = false;
            Image image = imageFromArray(array, "image", hasAlpha);
            WriteOptions options;
            options.format = depthNamed(depth);
            options.alpha = hasAlpha;
            check(checkSampleFormatFits(path, options.format, "depth"));
            Status written = internalError("not run");
            {
                py::gil_scoped_release release;
                written = writeImageJob(path, [&]() -> Result<ImageOutput> {
                    return ImageOutput{std::move(image), options};
                });
            }
            check(written);
        },
        py::arg("path"), py::arg("image"), py::arg("depth") = "auto",
        "write_image(path, image, depth='auto')\n\nA linear float32 H x W x 3|4 array written "
        "atomically (a temporary file renamed over `path`) through the CLI's codecs: 8/16-bit "
        "formats sRGB-encoded, EXR/HDR linear. depth: 'auto' (from the extension), '8', '16', "
        "'half', 'float'.");
    m.def(
        "blend8",
        [](const std::string& mode, const py::handle& src, const py::handle& dst) {
            const auto parsed = parseBlend8Mode(mode);
            if (!parsed)
                throw py::value_error(
                    "mode: expected alpha, alpha-shift, premultiplied or add, "
                    "got '" +
                    mode + "'");
            const Image8 s = image8FromArray(src, "src"), d = image8FromArray(dst, "dst");
            Result<Image8> out = internalError("not run");
            {
                py::gil_scoped_release release;
                out = blendImages8(*parsed, s, d);
            }
            Image8 r = unwrap(std::move(out));
            py::array_t<std::uint8_t> result({r.height, r.width, r.channels});
            std::copy(r.pixels.begin(), r.pixels.end(), result.mutable_data());
            return result;
        },
        py::arg("mode"), py::arg("src"), py::arg("dst"),
        "blend8(mode, src, dst) -> ndarray\n\nThe 1999 article's exact 8-bit blends on uint8 "
        "H x W x C arrays, as `flarekit blend` computes them: mode alpha, alpha-shift, "
        "premultiplied or add; src RGBA (RGB for add), dst RGB or RGBA; the result RGB.");
}

}  // namespace flarekit::python
