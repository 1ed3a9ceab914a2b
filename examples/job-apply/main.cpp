// SPDX-License-Identifier: Apache-2.0
// A front end in 40 lines: the library's apply job (flarekit/job/ApplyJob.h) on an image or a
// frame pattern, its warnings and progress shown, Ctrl-C-free cancellation left to the caller.
//   job-apply IN OUT [COLORSPACE_OUT]      (IN, OUT: image files or patterns such as shot.####.exr)
#include <flarekit/job/ApplyJob.h>
#include <flarekit/ocio/OcioTransform.h>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: job-apply IN OUT [COLORSPACE_OUT]\n");
        return 2;
    }
    flarekit::ApplyOptions options;  // every field has the CLI's default: the light is found
    options.input = argv[1];
    options.output = argv[2];
    if (argc > 3) {  // the output converted through OpenColorIO (flarekit::ocio)
        auto color = flarekit::createOcioTransform({"", argv[3], ""});
        if (!color) {
            std::fprintf(stderr, "%s\n", color.error().message.c_str());
            return 2;
        }
        options.color = *color;
    }
    flarekit::JobEvents events;
    events.warning = [](const std::string& line) {
        std::fprintf(stderr, "warning: %s\n", line.c_str());
    };
    events.progress = [](int done, int total) {
        std::printf("frame %d of %d written\n", done, total);
    };
    auto report = flarekit::runApplyJob(options, events);
    if (!report) {  // one line, as the CLI prints it
        std::fprintf(stderr, "%s\n", report.error().message.c_str());
        return 2;
    }
    if (report->sequence)
        std::printf("%s\n", flarekit::describeShotSummary("job-apply", report->shot).c_str());
    std::printf("written: %s\n", argv[2]);
    return 0;
}
