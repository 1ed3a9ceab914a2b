// SPDX-License-Identifier: Apache-2.0
// Image uploads and read-backs through pixel buffer objects: the frame moves in bands through
// two persistently mapped buffers, so the CPU's copy of one band (and its float/half
// conversion) overlaps the GPU's transfer of the other, and no call waits for the whole frame.
// Half floats halve the bytes moved; a caller uses them where they lose nothing it keeps.
#pragma once

#include "gl/GlObjects.h"

namespace flarekit::gl {

class PixelTransfer {
  public:
    PixelTransfer() = default;
    ~PixelTransfer();
    PixelTransfer(PixelTransfer&&) = delete;
    PixelTransfer& operator=(PixelTransfer&&) = delete;

    //! Image rows into level 0 of `texture` (image row y is texture row y). With `half`, the
    //! values go as IEEE halves (the texture should then be RGBA16F): exact only for values that
    //! are halves already, as those read from a half-float EXR.
    Status upload(GLuint texture, const Image& image, bool half);
    //! Level 0 of a width x height `texture` into `out` (resized when its size differs), as
    //! floats or, with `half`, as halves widened on the CPU.
    Status download(GLuint texture, int width, int height, bool half, Image& out);

  private:
    struct Ring {
        Buffer buffers[2];
        void* mapped[2] = {nullptr, nullptr};
        GLsync fences[2] = {nullptr, nullptr};
        std::size_t bytes = 0;  //!< per buffer
    };
    Status prepare(Ring& ring, std::size_t bytes, bool forWriting);
    static void wait(Ring& ring, int slot);
    static void release(Ring& ring);
    Ring m_upload, m_download;
};

}  // namespace flarekit::gl
