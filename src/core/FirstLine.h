// SPDX-License-Identifier: Apache-2.0
// What flarekit's one-line errors quote: the first line of a (possibly multi-line) library
// message, trimmed (OpenImageIO, GL info logs), and excerpts of input text cut to a length.
#pragma once

#include <algorithm>
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

//! The length of the valid UTF-8 sequence at `text[i]` (2 to 4 bytes: no overlong forms, no
//! surrogates, nothing past U+10FFFF), or 0.
inline std::size_t utf8SequenceAt(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned lead = byte(i);
    const std::size_t n = lead >= 0xC2 && lead <= 0xDF   ? 2
                          : lead >= 0xE0 && lead <= 0xEF ? 3
                          : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                         : 0;
    if (n == 0 || i + n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
    const unsigned second = byte(i + 1);
    if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) ||
        (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second > 0x8F))
        return 0;
    return n;
}

//! `text` safe to print on a terminal: control bytes (an escape sequence that recolours the
//! terminal or sets its title, a newline that would cut the line) and bytes that are not valid
//! UTF-8 written as \xNN; printable ASCII and valid UTF-8 as they are.
inline std::string printable(std::string_view text) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += char(c), ++i;
        } else if (const std::size_t n = c >= 0x80 ? utf8SequenceAt(text, i) : 0; n > 0) {
            out.append(text.substr(i, n)), i += n;
        } else {
            out.append("\\x").append(1, kHex[c >> 4]).append(1, kHex[c & 15]), ++i;
        }
    }
    return out;
}

//! A message as one line for a terminal or a log: trailing blanks dropped, printable(), and no
//! more than 1,000 characters.
inline std::string cappedLine(std::string_view message) {
    // 1,000 characters: the longest real message (a list of every known key) fits; a hostile
    // input that echoes megabytes of itself does not reach the terminal. What is cut is the
    // values: the longest words (a 4 KB path, a value without spaces) lose their middle down to
    // 60 characters, first to last, so the reason after them ("File name too long") stays.
    constexpr std::size_t kMax = 1000, kWord = 60;
    std::string_view text = message;
    while (!text.empty() && std::string_view(" \t\r\n").find(text.back()) != std::string_view::npos)
        text.remove_suffix(1);
    std::string line = printable(text);
    while (line.size() > kMax) {
        std::size_t longest = 0, at = 0;
        for (std::size_t i = 0; i < line.size();) {
            const std::size_t end = std::min(line.find(' ', i), line.size());
            if (end - i > longest) longest = end - i, at = i;
            i = end + 1;
        }
        if (longest <= kWord) break;
        // The word's start and its end (a path's file name), the cut never inside a UTF-8
        // sequence.
        std::size_t head = kWord / 2, tail = at + longest - (kWord - head - 3);
        while (head > 0 && (static_cast<unsigned char>(line[at + head]) & 0xC0) == 0x80) --head;
        while ((static_cast<unsigned char>(line[tail]) & 0xC0) == 0x80) ++tail;
        line.replace(at + head, tail - at - head, "...");
    }
    return excerpt(line, kMax);
}

}  // namespace flarekit
