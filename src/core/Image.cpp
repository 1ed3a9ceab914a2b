// SPDX-License-Identifier: Apache-2.0
#include "flarekit/Image.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstring>
#include <new>

#include "core/Check.h"

namespace flarekit {

void* PixelMemory::allocate(std::size_t bytes) {
    if (bytes < kMappedBytes) return ::operator new(bytes);
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return p;
}

void PixelMemory::deallocate(void* p, std::size_t bytes) noexcept {
    if (!p) return;
    if (bytes < kMappedBytes) {
        ::operator delete(p);
    } else {
        ::munmap(p, bytes);
    }
}

Image::Image(int width, int height) : m_width(width), m_height(height) {
    FK_CHECK(width >= 0 && height >= 0, "width=" << width << " height=" << height);
    const std::size_t n = std::size_t(width) * std::size_t(height) * 4;
    m_data.resize(n);  // default-initialised (PixelAllocator)
    // Mapped buffers arrive zeroed from the kernel; heap ones are cleared here (an empty image
    // has no buffer at all: memset may not be handed its null pointer).
    if (n > 0 && n * sizeof(float) < PixelMemory::kMappedBytes)
        std::memset(static_cast<void*>(m_data.data()), 0, n * sizeof(float));
}

void Image::scale(float k) {
    for (float& v : m_data) v *= k;
}

void Image::fill(Rgba value) {
    auto* px = reinterpret_cast<Rgba*>(m_data.data());
    std::fill(px, px + pixelCount(), value);
}

}  // namespace flarekit
