// SPDX-License-Identifier: Apache-2.0
// The seeds' diagnostic views of the drive's shown frame, for the bottom strip: the visibility
// method's working textures (GPG2 texture masking's sun map and intensity map, the Burnout
// chain's mask, 14x14 grid and downsamples; kept with each frame by DrivePlayback) and the same
// moment of the drive through the emulated PSP GE (Burnout Dominator's trick: its 14x14 mask,
// the bilinear chain, the flare's CLUT before and after the GE renders into it, the frame). The
// PSP frame is made on a thread of its own, so scrubbing the timeline never waits for it.
#pragma once

#include <future>
#include <optional>
#include <string>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Psp.h"
#include "flarekit/Result.h"
#include "flarekit/gl/GpuVisibility.h"

namespace flarekit::studio {

struct DiagnosticPicture {
    std::string name;  //!< shown under it; a file stem when written
    Image8 image;      //!< RGBA
};

//! A method's working texture to 8 bits, linear (data, not a picture), scaled to its own peak
//! over red, green and blue: a chain level's texels are shares of a cell, a few hundredths,
//! and would show black; ratios between channels and texels are kept. Alpha opaque.
DiagnosticPicture methodPicture(const MethodView& view);

//! The drive at `seconds` through the emulated PSP: its input (the occluders ray-cast at
//! 480x272, the sun), the trick's result and its steps as pictures.
struct PspDiagnostics {
    psp::PspFrameInput input;
    psp::PspFrameResult result;
    std::vector<DiagnosticPicture> pictures;
};
Result<PspDiagnostics> pspDiagnosticsAt(double seconds);

//! Writes `method` as method-NAME.png and the PSP frame as psp-STEP.png, psp-occluders.png (the
//! 480x272 mask, white where something is in front of the sun) and psp.txt (the sun's pixel,
//! the coverage byte, the CLUT's alpha, the mask's visible pixels) into `dir`, made when
//! missing. Names: spaces become dashes.
Status writeDiagnostics(const std::string& dir, const std::vector<DiagnosticPicture>& method,
                        const PspDiagnostics& psp);

//! pspDiagnosticsAt on a worker: the newest request is made after the one running.
class PspDiagnosticsWorker {
  public:
    ~PspDiagnosticsWorker();
    //! Asks for drive frame `frame` (at `seconds`) unless it is made or being made.
    void request(int frame, double seconds);
    //! Collects a finished frame; the latest made (frame index and result), if any.
    const std::optional<std::pair<int, Result<PspDiagnostics>>>& latest();

  private:
    std::future<Result<PspDiagnostics>> m_running;
    int m_runningFrame = -1;
    std::optional<std::pair<int, double>> m_queued;
    std::optional<std::pair<int, Result<PspDiagnostics>>> m_latest;
};

}  // namespace flarekit::studio
