// SPDX-License-Identifier: Apache-2.0
#include "flarekit/Image.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <mutex>
#include <new>
#include <utility>

#include "core/Check.h"

namespace flarekit {

namespace {

// Address Sanitizer must see every buffer unmapped when it is freed: a recycled one would hide
// a use after free.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kRecycle = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kRecycle = false;
#else
constexpr bool kRecycle = true;
#endif
#else
constexpr bool kRecycle = true;
#endif

//! Large buffers freed recently, kept for the next allocation of the same size. Jobs make and
//! drop images of one size over and over (a shot's frames, a chain's passes, the generator's
//! layers), and the first touch of fresh pages is what such an image costs on a cloud VM:
//! 4 MiB took 11 ms on the 2-vCPU VM of docs/benchmarks.md, while clearing a recycled one takes
//! about a tenth of that. At most kRecycledBytes are kept, in buffers of at most
//! kLargestRecycled (a 4K RGBA float frame is 127 MiB and is always unmapped).
constexpr std::size_t kRecycledBytes = std::size_t(128) << 20;
constexpr std::size_t kLargestRecycled = std::size_t(32) << 20;

struct Recycled {
    std::mutex mutex;
    std::vector<std::pair<void*, std::size_t>> buffers;  //!< oldest first
    std::size_t bytes = 0;
};
//! Never destroyed: an image may be freed during static destruction.
Recycled& recycled() {
    static auto* pool = new Recycled;
    return *pool;
}

void* takeRecycled(std::size_t bytes) {
    Recycled& pool = recycled();
    std::lock_guard lock(pool.mutex);
    for (auto it = pool.buffers.rbegin(); it != pool.buffers.rend(); ++it) {
        if (it->second != bytes) continue;
        void* p = it->first;
        pool.buffers.erase(std::next(it).base());
        pool.bytes -= bytes;
        return p;
    }
    return nullptr;
}

//! Keeps `p` for reuse, unmapping the oldest buffers that no longer fit.
void recycle(void* p, std::size_t bytes) {
    std::vector<std::pair<void*, std::size_t>> dropped;
    {
        Recycled& pool = recycled();
        std::lock_guard lock(pool.mutex);
        pool.buffers.push_back({p, bytes});
        pool.bytes += bytes;
        while (pool.bytes > kRecycledBytes) {
            dropped.push_back(pool.buffers.front());
            pool.bytes -= pool.buffers.front().second;
            pool.buffers.erase(pool.buffers.begin());
        }
    }
    for (const auto& [q, n] : dropped) ::munmap(q, n);
}

//! Set while an Image(w, h, Uncleared) takes its buffer: a recycled one is then not cleared.
thread_local bool t_uncleared = false;

}  // namespace

void* PixelMemory::allocate(std::size_t bytes) {
    if (bytes < kMappedBytes) return ::operator new(bytes);
    if (kRecycle && bytes <= kLargestRecycled) {
        if (void* p = takeRecycled(bytes)) {
            if (!t_uncleared) std::memset(p, 0, bytes);  // as a fresh mapping arrives
            return p;
        }
    }
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return p;
}

void PixelMemory::deallocate(void* p, std::size_t bytes) noexcept {
    if (!p) return;
    if (bytes < kMappedBytes) {
        ::operator delete(p);
    } else if (kRecycle && bytes <= kLargestRecycled) {
        try {
            recycle(p, bytes);
        } catch (...) {  // no memory for the list: unmapped as before
            ::munmap(p, bytes);
        }
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

Image::Image(int width, int height, Uncleared) : m_width(width), m_height(height) {
    FK_CHECK(width >= 0 && height >= 0, "width=" << width << " height=" << height);
    struct Flag {  // cleared again however resize leaves (bad_alloc included)
        Flag() { t_uncleared = true; }
        ~Flag() { t_uncleared = false; }
    } flag;
    m_data.resize(std::size_t(width) * std::size_t(height) * 4);  // default-initialised
}

void Image::scale(float k) {
    for (float& v : m_data) v *= k;
}

void Image::fill(Rgba value) {
    auto* px = reinterpret_cast<Rgba*>(m_data.data());
    std::fill(px, px + pixelCount(), value);
}

}  // namespace flarekit
