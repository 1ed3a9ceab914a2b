// SPDX-License-Identifier: Apache-2.0
// `flarekit psp burnout|ridge-racer` as a library job: a mask file in, the GE frame, its steps
// and its command trace out.
#include <filesystem>

#include "core/LibraryNoise.h"
#include "core/SafeWrite.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Psp.h"

namespace flarekit::psp {

Result<PspFrameResult> runPspFrameJob(PspTrick trick, const PspFrameJobOptions& o) {
    auto mask = [&] {
        LibraryNoiseFilter filter;  // libpng's own lines repeat the one error reported
        return readImage8(o.occluders);
    }();
    if (!mask) return mask.error();
    auto occluders = occludersFromMask(*mask, o.occluders);
    if (!occluders) return occluders.error();
    if (!o.dumpDir.empty())
        if (Status s = makeOutputDirectory(o.dumpDir); !s) return s.error();
    PspFrameInput in;
    in.occluders = std::move(*occluders);
    in.sunX = o.sunX, in.sunY = o.sunY;
    in.naive = o.naive;
    in.keepSteps = !o.dumpDir.empty();
    in.trace = !o.traceFile.empty();
    auto r = runPspFrame(trick, in);
    if (!r) return r.error();
    if (Status s = writeImage8(o.output, r->frame, o.encode); !s) return s.error();
    for (const PspStep& step : r->steps) {
        const std::string path = (std::filesystem::path(o.dumpDir) / (step.name + ".png")).string();
        if (Status s = writeImage8(path, step.image, o.encode); !s) return s.error();
    }
    if (!o.traceFile.empty()) {
        std::string text;
        for (const std::string& line : r->trace) text += line + "\n";
        if (Status s = writeFileSafely(o.traceFile, text); !s) return s.error();
    }
    return r;
}

}  // namespace flarekit::psp
