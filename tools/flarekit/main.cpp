// flarekit: the command-line tool. One subcommand per job; each lives in its own file.
#include <cstdio>
#include <exception>

#include "Common.h"

int main(int argc, char** argv) {
    using namespace flarekit::cli;
    CLI::App app{"flarekit: lens flares for images and scenes (sprite flares after Tanczos 1999)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "flarekit 0.1.0");
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
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::fprintf(stderr, "flarekit: %s (see flarekit --help)\n", e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "flarekit: internal error: %s\n", e.what());
        return kExitInternal;
    }
    return exitCode;
}
