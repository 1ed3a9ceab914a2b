// flarekit: the command-line tool. One subcommand per job; each lives in its own file.
#include <cstdio>
#include <exception>

#include "Common.h"
#include "core/Interrupt.h"

int main(int argc, char** argv) {
    using namespace flarekit::cli;
    CLI::App app{"flarekit: lens flares for images and scenes (sprite flares after Tanczos 1999)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "flarekit " FLAREKIT_VERSION_STRING);
    int exitCode = kExitOk;
    addBlendCommand(app, exitCode);
    addApplyCommand(app, exitCode);
    addElementsCommand(app, exitCode);
    addPresetsCommand(app, exitCode);
    addVisibilityCommand(app, exitCode);
    addRenderCommand(app, exitCode);
    addLightsCommand(app, exitCode);
    addDemoCommand(app, exitCode);
    addPspCommand(app, exitCode);
    addPostFxCommand(app, exitCode);
    flarekit::installInterruptHandlers();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::fprintf(stderr, "flarekit: %s (see flarekit --help)\n", cappedLine(e.what()).c_str());
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "flarekit: internal error: %s\n", cappedLine(e.what()).c_str());
        return kExitInternal;
    }
    return finishProcess(exitCode);
}
