// SPDX-License-Identifier: Apache-2.0
// flarekit: the command-line tool. One subcommand per job; each lives in its own file.
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "Common.h"
#include "ParamOptions.h"
#include "core/Interrupt.h"
#include "flarekit/ImageIO.h"
#include "flarekit/Limits.h"

namespace {

//! --max-memory / FLAREKIT_MAX_MEMORY and --max-pixels-per-byte into the library's limits;
//! a one-line error for a malformed value.
flarekit::Status applyLimits(const std::string& maxMemory, double maxPixelsPerByte) {
    flarekit::ResourceLimits limits;
    std::string memory = maxMemory, source = "--max-memory";
    if (memory.empty()) {
        if (const char* env = std::getenv("FLAREKIT_MAX_MEMORY"); env && *env) {
            memory = env;
            source = "FLAREKIT_MAX_MEMORY";
        }
    }
    if (!memory.empty()) {
        const auto bytes = flarekit::parseByteSize(memory);
        if (!bytes) {
            return flarekit::invalidInput(source +
                                          ": expected a size such as 4G, 512M or 8GiB, got '" +
                                          flarekit::cli::excerptLine(memory, 60) + "'");
        }
        limits.maxMemoryBytes = *bytes;
    }
    if (maxPixelsPerByte > 0) limits.maxPixelsPerFileByte = maxPixelsPerByte;
    flarekit::setResourceLimits(limits);
    return flarekit::Ok{};
}

}  // namespace

int main(int argc, char** argv) {
    using namespace flarekit::cli;
    if (argc > 1 && std::string_view(argv[1]) == "studio") return runStudioCommand(argc, argv);
    CLI::App app{"flarekit: lens flares for images and scenes (sprite flares after Tanczos 1999)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "flarekit " FLAREKIT_VERSION_STRING);
    // Global options, accepted before or after the subcommand (fallthrough).
    app.fallthrough();
    std::string maxMemory;
    double maxPixelsPerByte = 0;
    app.add_option("--max-memory", maxMemory,
                   "memory budget of a job, e.g. 8G (default 4G, or FLAREKIT_MAX_MEMORY): a job "
                   "whose estimated peak exceeds it is refused before it starts");
    app.add_option("--max-pixels-per-byte", maxPixelsPerByte,
                   "refuse images over 16 MP claiming more pixels per file byte than this "
                   "(default 10000: decompression bombs, truncated files)")
        ->check(CLI::PositiveNumber);
    flarekit::EncodeSettings& encode = encodeSettings();
    addParamOption<flarekit::EncodeSettings>(&app, flarekit::kEncodeParams, "png_compression",
                                             encode);
    std::string exrCompression =
        "piz";  // shown as the default; the input's own is kept unless given
    CLI::Option* exrOption =
        app.add_option(
               "--exr-compression", exrCompression,
               "compression of the EXRs written: piz (default; lossless, and on an 8-megapixel "
               "photograph 3x as fast as zip and 13% smaller), zip, zips, rle, none, or lossy "
               "pxr24, "
               "b44, b44a, dwaa, dwab; an EXR input's own compression is kept unless this is given")
            ->check(CLI::IsMember(flarekit::exrCompressionNames()));
    addParamOption<flarekit::EncodeSettings>(&app, flarekit::kEncodeParams, "exr_zip_level",
                                             encode);
    int exitCode = kExitOk;
    addBlendCommand(app, exitCode);
    addApplyCommand(app, exitCode);
    addElementsCommand(app, exitCode);
    addPresetsCommand(app, exitCode);
    addConvertCommand(app, exitCode);
    addVisibilityCommand(app, exitCode);
    addRenderCommand(app, exitCode);
    addLightsCommand(app, exitCode);
    addDemoCommand(app, exitCode);
    addPspCommand(app, exitCode);
    addPostFxCommand(app, exitCode);
    addLensCommand(app, exitCode);
    addSynthCommand(app, exitCode);
    addStudioCommand(app);
    // The limits are in place before any subcommand's callback runs.
    app.parse_complete_callback([&] {
        if (flarekit::Status s = applyLimits(maxMemory, maxPixelsPerByte); !s)
            throw CLI::ValidationError(s.error().message);
        if (exrOption->count() > 0) encode.exrCompression = exrCompression;
        if (flarekit::Status s = flarekit::checkEncodeSettings(encode); !s)
            throw CLI::ValidationError(s.error().message);
    });
    flarekit::installInterruptHandlers();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::fprintf(stderr, "flarekit: %s (see flarekit --help)\n",
                     flarekit::cappedLine(e.what()).c_str());
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "flarekit: internal error: %s\n",
                     flarekit::cappedLine(e.what()).c_str());
        return kExitInternal;
    }
    return finishProcess(exitCode);
}
