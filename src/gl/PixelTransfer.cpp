// SPDX-License-Identifier: Apache-2.0
#include "gl/PixelTransfer.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "core/HalfFloat.h"
#include "core/Parallel.h"

namespace flarekit::gl {

namespace {

//! Bytes per band buffer: 8 MiB, a few bands of a 4K frame (61 KB a float row) so two are in
//! flight while the rest is copied, and small beside the frame itself.
constexpr std::size_t kBandBytes = std::size_t(8) << 20;

int bandRows(int width, std::size_t pixelBytes) {
    return int(std::max<std::size_t>(1, kBandBytes / (std::size_t(width) * pixelBytes)));
}

}  // namespace

PixelTransfer::~PixelTransfer() {
    release(m_upload);
    release(m_download);
}

void PixelTransfer::release(Ring& ring) {
    for (int i = 0; i < 2; ++i) {
        if (ring.fences[i]) glDeleteSync(ring.fences[i]);
        ring.fences[i] = nullptr;
        if (ring.mapped[i]) glUnmapNamedBuffer(ring.buffers[i].get());
        ring.mapped[i] = nullptr;
        ring.buffers[i].reset();
    }
    ring.bytes = 0;
}

Status PixelTransfer::prepare(Ring& ring, std::size_t bytes, bool forWriting) {
    if (ring.bytes >= bytes) return Ok{};
    release(ring);
    // Persistent and coherent: mapped once for the buffer's life; the fences order the CPU's
    // and the GPU's use of each band.
    const GLbitfield access = (forWriting ? GL_MAP_WRITE_BIT : GL_MAP_READ_BIT) |
                              GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    for (int i = 0; i < 2; ++i) {
        GLuint name = 0;
        glCreateBuffers(1, &name);
        ring.buffers[i] = Buffer(name);
        glNamedBufferStorage(name, GLsizeiptr(bytes), nullptr,
                             access | (forWriting ? 0u : GLbitfield(GL_CLIENT_STORAGE_BIT)));
        ring.mapped[i] = glMapNamedBufferRange(name, 0, GLsizeiptr(bytes), access);
        if (!ring.mapped[i]) {
            release(ring);
            return checkError("mapping a pixel buffer");
        }
    }
    ring.bytes = bytes;
    return checkError("creating the pixel buffers");
}

void PixelTransfer::wait(Ring& ring, int slot) {
    if (!ring.fences[slot]) return;
    // Flushing on the first wait: the fence must reach the GPU to ever be signalled.
    while (glClientWaitSync(ring.fences[slot], GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) ==
           GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(ring.fences[slot]);
    ring.fences[slot] = nullptr;
}

Status PixelTransfer::upload(GLuint texture, const Image& image, bool half) {
    const int w = image.width(), h = image.height();
    const std::size_t pixelBytes = half ? 8 : 16;
    const int rows = std::min(h, bandRows(w, pixelBytes));
    if (Status s = prepare(m_upload, std::size_t(rows) * std::size_t(w) * pixelBytes, true); !s)
        return s;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int y = 0, band = 0; y < h; y += rows, ++band) {
        const int slot = band % 2, n = std::min(rows, h - y);
        wait(m_upload, slot);  // the GPU has finished reading this buffer's previous band
        void* to = m_upload.mapped[slot];
        parallelFor(0, n, 16, [&](int r0, int r1) {
            const std::size_t first = std::size_t(r0) * std::size_t(w),
                              count = std::size_t(r1 - r0) * std::size_t(w);
            if (half) {
                floatsToHalf(image.row(y + r0), count, 4,
                             static_cast<std::uint16_t*>(to) + first * 4);
            } else {
                std::memcpy(static_cast<float*>(to) + first * 4, image.row(y + r0), count * 16);
            }
        });
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, m_upload.buffers[slot].get());
        glTextureSubImage2D(texture, 0, 0, y, w, n, GL_RGBA, half ? GL_HALF_FLOAT : GL_FLOAT,
                            nullptr);
        m_upload.fences[slot] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    }
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    return checkError("uploading an image");
}

Status PixelTransfer::download(GLuint texture, int w, int h, bool half, Image& out) {
    if (out.width() != w || out.height() != h) out = Image(w, h);
    const std::size_t pixelBytes = half ? 8 : 16;
    const int rows = std::min(h, bandRows(w, pixelBytes));
    if (Status s = prepare(m_download, std::size_t(rows) * std::size_t(w) * pixelBytes, false); !s)
        return s;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    const GLenum type = half ? GL_HALF_FLOAT : GL_FLOAT;
    const auto request = [&](int band) {
        const int slot = band % 2, y = band * rows, n = std::min(rows, h - y);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, m_download.buffers[slot].get());
        glGetTextureSubImage(texture, 0, 0, y, 0, w, n, 1, GL_RGBA, type,
                             GLsizei(std::size_t(n) * std::size_t(w) * pixelBytes), nullptr);
        m_download.fences[slot] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    };
    const int bands = (h + rows - 1) / rows;
    request(0);
    for (int band = 0; band < bands; ++band) {
        if (band + 1 < bands) request(band + 1);  // in flight while this band is copied
        const int slot = band % 2, y = band * rows, n = std::min(rows, h - y);
        wait(m_download, slot);
        const void* from = m_download.mapped[slot];
        parallelFor(0, n, 16, [&](int r0, int r1) {
            const std::size_t first = std::size_t(r0) * std::size_t(w) * 4,
                              count = std::size_t(r1 - r0) * std::size_t(w) * 4;
            if (half) {
                halfsToFloats(static_cast<const std::uint16_t*>(from) + first, count,
                              out.row(y + r0));
            } else {
                std::memcpy(out.row(y + r0), static_cast<const float*>(from) + first, count * 4);
            }
        });
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    return checkError("reading an image back");
}

}  // namespace flarekit::gl
