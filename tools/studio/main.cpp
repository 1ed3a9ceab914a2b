// SPDX-License-Identifier: Apache-2.0
// flarekit-studio: the live flare designer. `flarekit studio ...` runs this program (kept out of
// the CLI so that the CLI's start-up does not load X11, GLFW and ImGui).
#include <CLI/CLI.hpp>

#include <cstdio>

#include "App.h"

int main(int argc, char** argv) {
    using namespace flarekit::studio;
    StudioOptions o;
    CLI::App app{"flarekit studio: a live flare designer (GLFW + Dear ImGui)", "flarekit studio"};
    bool helpScript = false;
    app.add_option("file", o.file, "an image (any format the CLI reads) or a preset JSON to open");
    app.add_option("--preset", o.preset, "sprite preset to start with (name or JSON file)");
    app.add_option("--script", o.script,
                   "play the actions of this JSON file, then exit (see --help-script)");
    app.add_option("--screenshot", o.screenshot,
                   "draw the window, write it to this PNG and exit (with --script: where the "
                   "script's screenshot actions say)");
    std::string size = "1600x900";
    app.add_option("--size", size, "window size WIDTHxHEIGHT")->capture_default_str();
    app.add_flag("--stats", o.stats, "frames drawn and preview times on stderr at exit");
    app.add_flag("--help-script", helpScript, "the script's actions as a Markdown table");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    if (helpScript) {
        std::fputs(scriptReference().c_str(), stdout);
        return 0;
    }
    if (std::sscanf(size.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 640 ||
        o.height < 480 || o.width > 8192 || o.height > 8192) {
        std::fprintf(stderr,
                     "flarekit studio: --size: expected WIDTHxHEIGHT from 640x480 to "
                     "8192x8192, got %s\n",
                     size.c_str());
        return 2;
    }
    return runStudio(o);
}
