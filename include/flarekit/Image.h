// SPDX-License-Identifier: Apache-2.0
// Image: linear-light float RGBA, row-major, top row first. Everything inside flarekit works
// on this; 8-bit files are sRGB-decoded on read and encoded on write (see ImageIO.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace flarekit {

//! The allocator of pixel buffers. Large buffers (1 MiB and up) are their own anonymous
//! mappings, which the kernel hands over zeroed, so a new image is not cleared twice. They are
//! not marked for transparent huge pages: on a cloud VM that hands freed 2 MiB blocks back to
//! the host (virtio-balloon free page reporting), a huge page's first touch costs about 3 ms per
//! MiB, 6x a plain page's (docs/formats.md). Elements are default-initialised: Image zeroes the
//! small ones itself.
struct PixelMemory {
    static constexpr std::size_t kMappedBytes = std::size_t(1) << 20;
    static void* allocate(std::size_t bytes);
    static void deallocate(void* p, std::size_t bytes) noexcept;
};

template <typename T>
struct PixelAllocator {
    using value_type = T;
    PixelAllocator() = default;
    template <typename U>
    PixelAllocator(const PixelAllocator<U>&) noexcept {}  // NOLINT(google-explicit-constructor)
    T* allocate(std::size_t n) { return static_cast<T*>(PixelMemory::allocate(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { PixelMemory::deallocate(p, n * sizeof(T)); }
    template <typename U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;  // default-initialised: no write to fresh pages
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    friend bool operator==(const PixelAllocator&, const PixelAllocator&) { return true; }
};

struct Rgba {
    float r = 0.f, g = 0.f, b = 0.f, a = 0.f;
};

class Image {
  public:
    Image() = default;
    Image(int width, int height);  //!< zero-filled (transparent black)
    //! Tag of the constructor below.
    struct Uncleared {};
    //! An image whose every pixel the caller is about to write: its buffer is not cleared, so a
    //! recycled one still holds an earlier image's pixels until then.
    Image(int width, int height, Uncleared);

    int width() const { return m_width; }
    int height() const { return m_height; }
    std::size_t pixelCount() const { return std::size_t(m_width) * std::size_t(m_height); }
    bool empty() const { return m_width == 0 || m_height == 0; }

    float* row(int y) { return m_data.data() + std::size_t(y) * std::size_t(m_width) * 4; }
    const float* row(int y) const {
        return m_data.data() + std::size_t(y) * std::size_t(m_width) * 4;
    }
    Rgba& at(int x, int y) { return reinterpret_cast<Rgba*>(row(y))[x]; }
    const Rgba& at(int x, int y) const { return reinterpret_cast<const Rgba*>(row(y))[x]; }
    float* data() { return m_data.data(); }
    const float* data() const { return m_data.data(); }

    void fill(Rgba value);
    void scale(float k);  //!< every channel (alpha too) x k

  private:
    int m_width = 0;
    int m_height = 0;
    std::vector<float, PixelAllocator<float>> m_data;
};

static_assert(sizeof(Rgba) == 4 * sizeof(float), "Rgba must alias four packed floats");

//! Largest accepted width or height, in pixels (a "> 32768-pixel image" is rejected as bad input).
inline constexpr int kMaxImageSide = 32768;
//! Largest accepted pixel count: 2^28 pixels is 4 GiB of float RGBA, a sixth of a 24 GiB machine.
inline constexpr std::size_t kMaxImagePixels = std::size_t(1) << 28;

//! 8-bit interleaved image, used by the exact seed-002 blend path (no colour conversion).
struct Image8 {
    int width = 0;
    int height = 0;
    int channels = 0;  //!< 1..4
    std::vector<std::uint8_t> pixels;
};

}  // namespace flarekit
