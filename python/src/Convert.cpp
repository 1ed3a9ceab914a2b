// SPDX-License-Identifier: Apache-2.0
#include "Convert.h"

#include <cstring>
#include <regex>

#include "flarekit/Limits.h"

namespace flarekit::python {

std::string pythonSpelling(const std::string& message) {
    std::string text =
        std::regex_replace(message, std::regex("--max-memory or FLAREKIT_MAX_MEMORY"),
                           "flarekit.set_max_memory(BYTES) or FLAREKIT_MAX_MEMORY");
    // The light's two spellings: found (--light auto) and placed (--light X,Y).
    text = std::regex_replace(text, std::regex("--light auto"), "light=None");
    text = std::regex_replace(text, std::regex("--light X,Y"), "light=(x, y)");
    // A flag after a space, a start or an opening bracket: "--flux-mode" -> "flux_mode".
    std::string out;
    std::smatch m;
    static const std::regex flag("(^|[\\s(\"'])--([a-z][a-z0-9-]*)");
    std::string::const_iterator from = text.cbegin();
    while (std::regex_search(from, text.cend(), m, flag)) {
        out.append(from, m[0].first);
        std::string name = m[2].str();
        for (char& c : name)
            if (c == '-') c = '_';
        out += m[1].str() + name;
        from = m[0].second;
    }
    out.append(from, text.cend());
    return out;
}

void raise(const Error& error) {
    const std::string message = pythonSpelling(error.message);
    if (error.code == ErrorCode::InvalidInput || error.code == ErrorCode::Io)
        throw py::value_error(message);
    throw std::runtime_error(message);
}

Image imageFromArray(const py::handle& object, const std::string& what, bool& hasAlpha) {
    if (!py::isinstance<py::array>(object))
        throw py::value_error(what + ": expected a numpy array (float32, H x W x 3 or 4), got " +
                              std::string(py::str(py::type::of(object).attr("__name__"))));
    const py::array array = py::reinterpret_borrow<py::array>(object);
    if (!array.dtype().is(py::dtype::of<float>()))
        throw py::value_error(what + ": expected float32 samples (linear light), got " +
                              std::string(py::str(array.dtype())) +
                              " (convert with .astype(numpy.float32); 8-bit sRGB data: "
                              "flarekit.srgb_to_linear)");
    if (array.ndim() != 3 || (array.shape(2) != 3 && array.shape(2) != 4)) {
        std::string shape;
        for (py::ssize_t i = 0; i < array.ndim(); ++i)
            shape += (i ? " x " : "") + std::to_string(array.shape(i));
        throw py::value_error(what + ": expected shape H x W x 3 or H x W x 4, got " +
                              (shape.empty() ? "a scalar" : shape));
    }
    const py::ssize_t h = array.shape(0), w = array.shape(1), c = array.shape(2);
    if (w == 0 || h == 0)
        throw py::value_error(what + ": an image without pixels (" + std::to_string(w) + " x " +
                              std::to_string(h) + ")");
    if (w > kMaxImageSide || h > kMaxImageSide || std::size_t(w) * std::size_t(h) > kMaxImagePixels)
        throw py::value_error(what + ": " + std::to_string(w) + " x " + std::to_string(h) +
                              " is larger than flarekit takes (" + std::to_string(kMaxImageSide) +
                              " pixels a side, " + std::to_string(kMaxImagePixels) + " in all)");
    // The copy into RGBA floats is the job's input buffer (jobs write their result into it):
    // checked against the budget before it is made.
    check(checkMemory(what, double(w) * double(h) * 16.0, "its RGBA float copy"));
    hasAlpha = c == 4;
    Image image{int(w), int(h)};
    const auto* base = static_cast<const char*>(array.data());
    const py::ssize_t sy = array.strides(0), sx = array.strides(1), sc = array.strides(2);
    for (py::ssize_t y = 0; y < h; ++y) {
        float* out = image.row(int(y));
        for (py::ssize_t x = 0; x < w; ++x, out += 4) {
            const char* px = base + y * sy + x * sx;
            for (py::ssize_t k = 0; k < c; ++k) std::memcpy(out + k, px + k * sc, sizeof(float));
            if (c == 3) out[3] = 1.f;
        }
    }
    return image;
}

py::array arrayFromImage(Image&& image, int channels) {
    auto* owned = new Image(std::move(image));
    py::capsule owner(owned, [](void* p) { delete static_cast<Image*>(p); });
    const auto h = py::ssize_t(owned->height()), w = py::ssize_t(owned->width());
    const py::ssize_t f = sizeof(float);
    return py::array_t<float>({h, w, py::ssize_t(channels)}, {w * 4 * f, 4 * f, f}, owned->data(),
                              owner);
}

CollectedEvents::CollectedEvents() : m_lines(std::make_shared<Lines>()) {
    m_events.warning = [lines = m_lines](const std::string& line) {
        std::lock_guard lock(lines->mutex);
        lines->warnings.push_back(line);
    };
    m_events.info = [lines = m_lines](const std::string& line) {
        std::lock_guard lock(lines->mutex);
        lines->info.push_back(line);
    };
}

void CollectedEvents::emit() const {
    std::vector<std::string> warnings;
    {
        std::lock_guard lock(m_lines->mutex);
        warnings.swap(m_lines->warnings);
    }
    for (const std::string& line : warnings)
        if (PyErr_WarnEx(PyExc_UserWarning, pythonSpelling(line).c_str(), 2) < 0)
            throw py::error_already_set();
}

std::vector<std::string> CollectedEvents::infoLines() const {
    std::lock_guard lock(m_lines->mutex);
    return m_lines->info;
}

}  // namespace flarekit::python
