#include "flarekit/Image.h"

#include <algorithm>

#include "core/Check.h"

namespace flarekit {

Image::Image(int width, int height) : m_width(width), m_height(height) {
    FK_CHECK(width >= 0 && height >= 0, "width=" << width << " height=" << height);
    m_data.assign(std::size_t(width) * std::size_t(height) * 4, 0.f);
}

void Image::scale(float k) {
    for (float& v : m_data) v *= k;
}

void Image::fill(Rgba value) {
    auto* px = reinterpret_cast<Rgba*>(m_data.data());
    std::fill(px, px + pixelCount(), value);
}

}  // namespace flarekit
