// SPDX-License-Identifier: Apache-2.0
// flarekit-frei0r-metadata OUT.yml: writes the filter's MLT metadata (at build time);
// flarekit-frei0r-metadata --markdown: prints its parameter table (docs/hosts.md).
#include <cstdio>
#include <fstream>
#include <string>

#include "FilterSettings.h"

int main(int argc, char** argv) {
    if (argc == 2 && std::string(argv[1]) == "--markdown") {
        std::fputs(flarekit::frei0r::markdownTable().c_str(), stdout);
        return std::fflush(stdout) == 0 ? 0 : 1;
    }
    if (argc != 2) {
        std::fputs("usage: flarekit-frei0r-metadata OUT.yml | --markdown\n", stderr);
        return 2;
    }
    std::ofstream out(argv[1], std::ios::binary);
    out << flarekit::frei0r::mltMetadata();
    out.close();
    if (!out) {
        std::fprintf(stderr, "flarekit-frei0r-metadata: %s: cannot write\n", argv[1]);
        return 1;
    }
    return 0;
}
