// SPDX-License-Identifier: Apache-2.0
// The demo drive (flarekit/Demo.h) rendered frame by frame through the GL frame pipeline.
#pragma once

#include <memory>

#include "flarekit/Demo.h"
#include "flarekit/gl/FramePipeline.h"

namespace flarekit {

//! A frame of the drive: the pipeline's frame and when in the drive it is.
struct DemoFrame : PipelineFrame {
    double time = 0;  //!< seconds into the drive
};

//! Renders the demo frame by frame (in order: the temporal filter carries state). A GL
//! context must be current on the calling thread while it lives.
class DemoAnimation {
  public:
    static Result<DemoAnimation> create(const DemoSettings& settings, const Preset& preset);
    ~DemoAnimation();
    DemoAnimation(DemoAnimation&&) noexcept;
    DemoAnimation& operator=(DemoAnimation&&) noexcept;

    int frameCount() const;
    std::size_t primitiveCount() const;  //!< objects in the world (triangles, spheres, boxes)
    //! The next frame (0, 1, 2, ...); an error past the last.
    Result<DemoFrame> next();

  private:
    struct Impl;
    explicit DemoAnimation(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m;
};

}  // namespace flarekit
