// SPDX-License-Identifier: Apache-2.0
// What flarekit's one-line errors quote: the first line of a (possibly multi-line) library
// message, trimmed (OpenImageIO, GL info logs), and excerpts of input text cut to a length.
#pragma once

#include <string>
#include <string_view>

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

//! `text` cut to `max` characters, the last three "...": every echoed key, token or value. The
//! cut never falls inside a UTF-8 sequence (continuation bytes are 10xxxxxx), so the excerpt
//! stays valid UTF-8 when the text was.
inline std::string excerpt(std::string_view text, std::size_t max) {
    if (text.size() <= max) return std::string(text);
    std::size_t cut = max - 3;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return std::string(text.substr(0, cut)) + "...";
}

}  // namespace flarekit
