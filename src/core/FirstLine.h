// The first line of a (possibly multi-line) library message, trimmed: what flarekit's one-line
// errors quote from OpenImageIO and GL info logs.
#pragma once

#include <string>

namespace flarekit {

inline std::string firstLine(const std::string& text) {
    std::size_t begin = text.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos) return {};
    std::size_t end = text.find_first_of("\r\n", begin);
    std::string line =
        text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.pop_back();
    return line;
}

}  // namespace flarekit
