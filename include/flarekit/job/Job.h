// SPDX-License-Identifier: Apache-2.0
// What every job (apply, postfx, lens render, on one image or a shot) shares, whichever front end
// runs it: how it talks back (warnings, detail lines, progress, cancellation: callbacks, never
// prints), the colour transform at its two ends, reading its input and writing its output. The
// CLI, the Python module, the studio and the host plug-ins all call the jobs through this layer.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Result.h"
#include "flarekit/Tonemap.h"

namespace flarekit {

//! How a job reports while it runs. Every member may be empty (then it is silent, never
//! cancelled). Callbacks may be called from several threads at once (a shot's frames render in
//! parallel); each call is one whole line or one progress step.
struct JobEvents {
    //! Something the user should know that does not stop the job ("frames 5-7 are missing").
    std::function<void(const std::string& line)> warning;
    //! Detail a verbose front end shows (light candidates, pass times); no trailing newline.
    std::function<void(const std::string& line)> info;
    //! A shot's frames: `done` of `total` written (called in order, `done` rising).
    std::function<void(int done, int total)> progress;
    //! Progress inside one image, for work that takes minutes (a lens render's sources):
    //! `done` of `total` `what`s ("source") of `image` drawn.
    std::function<void(const std::string& image, const std::string& what, int done, int total)>
        steps;
    //! Polled between frames and inside long renders: true stops the job with an Interrupted
    //! error naming what was finished (each file written is complete).
    std::function<bool()> cancelled;

    void warn(const std::string& line) const {
        if (warning) warning(line);
    }
    void say(const std::string& line) const {
        if (info) info(line);
    }
    bool stopRequested() const { return cancelled && cancelled(); }
};

//! The colour spaces at a job's two ends: the input converted to the working space (linear
//! Rec.709, flarekit's scene_linear) after reading, the result converted to the output's space
//! before writing. Implementations must be safe to call from several threads at once.
//! flarekit/ocio/OcioTransform.h ships one over OpenColorIO; without one nothing changes
//! (8/16-bit files are sRGB, float files scene-linear Rec.709).
class ColorTransform {
  public:
    virtual ~ColorTransform() = default;
    //! `loaded` as decoded, to the working space.
    virtual void toWorking(LoadedImage& loaded) const = 0;
    //! The working-space result to the output's space; may set `options` (its tag, no second
    //! sRGB curve).
    virtual void toOutput(Image& image, WriteOptions& options) const = 0;
};

//! An image a job made and how to write it.
struct ImageOutput {
    Image image;
    WriteOptions options;
};

//! A job's input image: decoded as readImage does; more than 4 channels refused (flarekit
//! writes RGBA, so the others would be lost); NaN/Inf replaced with a warning. `job` is the
//! job's memory per input pixel, checked against the budget from the file's header.
//! `read.part`: a multi-part EXR's part to flare.
Result<LoadedImage> readJobInput(const std::string& path, const JobMemory& job,
                                 const JobEvents& events = {}, const ReadOptions& read = {});

//! A multi-part EXR input keeps its other parts only in an EXR output: any other `out` is
//! refused with one line naming the parts, before any work.
Status checkPartsFit(const LoadedImage& loaded, const std::string& in, const std::string& out);

//! An EXR input's extras (other channels, attributes, windows) for writing `out`: all of it to
//! an EXR; for another format a warning that its channels past RGBA are not written there.
std::shared_ptr<const ExrExtras> keptExtras(const LoadedImage& loaded, const std::string& in,
                                            const std::string& out, const JobEvents& events);

//! A job's passes as named channels of its EXR output (NAME.R, NAME.G, NAME.B: linear, float,
//! one file per frame, as compositing packages expect), beside what `extras` (the input's other
//! channels and header, or null) already carries.
using NamedLayer = std::pair<std::string, const Image*>;
std::shared_ptr<const ExrExtras> withLayerChannels(std::shared_ptr<const ExrExtras> extras,
                                                   const std::vector<NamedLayer>& layers);
//! Layers in the output need an EXR output: one line naming the option otherwise.
Status checkLayersFit(bool layersInOutput, const std::string& out);

//! A file a job touches, and what it is to the user ("the input", "--matte", "layer glow of
//! --layers"), as the refusal names it.
struct JobFile {
    std::string path;
    std::string role;
};
//! Every file a job will write (its output, each layer, each frame's) against every file it
//! reads (plate, matte, preset, track) and against the others it writes, by file identity (one
//! file under another name, through a link or `..`, a hard link): one line naming both, before
//! any work. A device (/dev/null) is never a clash; a read that does not exist cannot be.
Status checkJobFiles(const std::vector<JobFile>& reads, const std::vector<JobFile>& writes);

//! The Interrupted error of a job stopped by JobEvents::cancelled, `what` saying what it
//! finished: "interrupted by SIGTERM: ..." when a signal stopped it, else "cancelled: ...".
Error cancelledError(const std::string& what);

//! The tail of every one-image job: `out` checked before any work (a bad path costs nothing),
//! the work, one atomic write.
Status writeImageJob(const std::string& out, const std::function<Result<ImageOutput>()>& work);

//! The curve one of kToneOperatorNames names; nothing for any other word.
std::optional<ToneOperator> toneOperatorNamed(const std::string& name);

//! The default display curve of HDR data: HDR (float) input written to an 8/16-bit file goes
//! through Hable's filmic curve, which rolls a sun of 30,000 and its flare off into white over
//! several stops instead of clipping everything above 1 to a flat disc; its toe keeps the
//! shadows of the photograph. Float outputs stay linear and unclamped, and 8-bit input is
//! already display-referred: none. An empty `out` (an in-memory result, float): none.
ToneOperator defaultDisplayCurve(bool hdrInput, const std::string& out,
                                 SampleFormat requested = SampleFormat::Auto);

}  // namespace flarekit
