// SPDX-License-Identifier: Apache-2.0
// `flarekit studio [FILE] [--screenshot OUT.png] [--script ACTIONS.json] ...`: runs the studio
// program installed beside this one (flarekit-studio) with the arguments as given, before the
// CLI parses anything (the studio parses and documents its own options). The studio is a program
// of its own so that the CLI's start-up never loads X11, GLFW or Dear ImGui.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "Common.h"

namespace flarekit::cli {

void addStudioCommand(CLI::App& app) {
    // Listed in `flarekit --help`; runStudioCommand takes the command line before it is parsed.
    app.add_subcommand("studio",
                       "live flare designer in a window (GLFW + Dear ImGui): open an image, drag "
                       "the light, edit the preset with undo, save it, export renders; `flarekit "
                       "studio --help` for its options");
}

int runStudioCommand(int argc, char** argv) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    const fs::path studio = self.parent_path() / "flarekit-studio";
    if (ec || !fs::exists(studio, ec)) {
        std::fprintf(stderr,
                     "flarekit: studio: %s is not installed (built with FLAREKIT_STUDIO=OFF, or "
                     "without libglfw3-dev and libimgui-dev)\n",
                     studio.string().c_str());
        return kExitBadInput;
    }
    std::vector<char*> args{const_cast<char*>(studio.c_str())};
    for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
    args.push_back(nullptr);
    std::fflush(stdout);
    ::execv(studio.c_str(), args.data());
    std::fprintf(stderr, "flarekit: studio: cannot run %s: %s\n", studio.c_str(),
                 std::strerror(errno));
    return kExitBadInput;
}

}  // namespace flarekit::cli
