// SPDX-License-Identifier: Apache-2.0
// A headless OpenGL 4.5 core context through EGL, with no window and no X server. On a
// machine with a GPU driver the EGL device platform finds the GPU; elsewhere Mesa's
// surfaceless platform gives llvmpipe (software GL). Functions load through libepoxy.
#pragma once

#include <memory>
#include <string>

#include "flarekit/Result.h"

namespace flarekit::gl {

class HeadlessGl {
  public:
    //! Creates a context and makes it current on the calling thread. FLAREKIT_EGL_PLATFORM
    //! (device | surfaceless) forces one platform; by default devices are tried first.
    static Result<std::unique_ptr<HeadlessGl>> create();
    ~HeadlessGl();
    HeadlessGl(const HeadlessGl&) = delete;
    HeadlessGl& operator=(const HeadlessGl&) = delete;

    std::string renderer() const;  //!< GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version() const;   //!< GL_VERSION
    //! Mesa's llvmpipe or softpipe: the "GPU" is this CPU, so uploads in halves only add a
    //! conversion each way.
    bool software() const;
    const std::string& platform() const { return m_platform; }  //!< "device" or "surfaceless"

  private:
    HeadlessGl() = default;
    void* m_display = nullptr;
    void* m_context = nullptr;
    std::string m_platform;
};

//! HeadlessGl::create with Mesa's loader warnings held back: on failure its one line says what
//! was tried and what failed (with Mesa's first warning), instead of four lines on stderr.
Result<std::unique_ptr<HeadlessGl>> createQuietHeadlessGl();

//! A frame of width x height rendered with `msaa` samples per pixel in the current context:
//! refused when a side is over the context's limits (GL_MAX_TEXTURE_SIZE, renderbuffer,
//! viewport, framebuffer), naming `field` ("scene.json: image" gives "scene.json:
//! image.width: ..."), or when its render targets and copies are over the memory budget.
Status checkGlFrame(int width, int height, int msaa, const std::string& field);

//! createQuietHeadlessGl, then checkGlFrame in it: the context a job that renders one frame
//! size makes for itself.
Result<std::unique_ptr<HeadlessGl>> createFrameContext(int width, int height, int msaa,
                                                       const std::string& field);

}  // namespace flarekit::gl
