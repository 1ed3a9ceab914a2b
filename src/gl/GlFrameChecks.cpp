// SPDX-License-Identifier: Apache-2.0
// Creating the headless context quietly, and checking a frame against the context's limits and
// the memory budget before any GL object is made.
#include <epoxy/gl.h>

#include <algorithm>

#include "core/FirstLine.h"
#include "core/LibraryNoise.h"
#include "flarekit/Limits.h"
#include "flarekit/gl/HeadlessGl.h"

namespace flarekit::gl {

Result<std::unique_ptr<HeadlessGl>> createQuietHeadlessGl() {
    LibraryNoiseFilter filter(
        {"libEGL warning", "MESA-LOADER", "MESA:", "libGL error", "pci id", "\n"});
    auto gl = HeadlessGl::create();
    const std::string mesa = filter.finish();
    if (gl || mesa.empty()) return gl;
    Error e = gl.error();
    e.message += "; Mesa: " + excerpt(std::string_view(mesa).substr(0, mesa.find('\n')), 160);
    return e;
}

Status checkGlFrame(int width, int height, int msaa, const std::string& field) {
    GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0}, fbWidth = 0, fbHeight = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &fbWidth);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &fbHeight);
    // Each axis against every limit that bounds it (0: a limit the context does not report).
    struct Axis {
        int size;
        const char* side;
        GLint viewport, framebuffer;
        const char* framebufferName;
    };
    for (const Axis& a :
         {Axis{width, "width", viewport[0], fbWidth, "GL_MAX_FRAMEBUFFER_WIDTH"},
          Axis{height, "height", viewport[1], fbHeight, "GL_MAX_FRAMEBUFFER_HEIGHT"}}) {
        const std::pair<GLint, const char*> limits[] = {{texture, "GL_MAX_TEXTURE_SIZE"},
                                                        {renderbuffer, "GL_MAX_RENDERBUFFER_SIZE"},
                                                        {a.viewport, "GL_MAX_VIEWPORT_DIMS"},
                                                        {a.framebuffer, a.framebufferName}};
        for (const auto& [limit, name] : limits) {
            if (limit > 0 && a.size > limit) {
                return invalidInput(field + "." + a.side + ": " + std::to_string(a.size) +
                                    " is over this OpenGL's limit of " + std::to_string(limit) +
                                    " (" + name + ")");
            }
        }
    }
    // Per pixel: the HDR colour, depth and transmittance targets and their resolve (~32 bytes),
    // the read-back and the CPU image (32), 12 per extra MSAA sample; 256 MiB of process and
    // driver (Mesa's llvmpipe measured at ~250 MiB resident with a small frame).
    const double pixels = double(width) * double(height);
    return checkMemory(field, 256.0 * (1 << 20) + pixels * (64.0 + 12.0 * std::max(0, msaa - 1)),
                       std::to_string(width) + "x" + std::to_string(height) + " with " +
                           std::to_string(std::max(1, msaa)) + " sample(s) per pixel");
}

Result<std::unique_ptr<HeadlessGl>> createFrameContext(int width, int height, int msaa,
                                                       const std::string& field) {
    auto context = createQuietHeadlessGl();
    if (!context) return context.error();
    if (Status s = checkGlFrame(width, height, msaa, field); !s) return s.error();
    return context;
}

}  // namespace flarekit::gl
