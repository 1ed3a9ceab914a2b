// SPDX-License-Identifier: Apache-2.0
// JSON input shared by presets and scenes: parse errors and value excerpts in the one-line
// "file: field: ..." style, and reading a text file. Included only by the JSON readers, so
// nlohmann-json stays out of every other translation unit.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <string_view>

#include "core/FirstLine.h"
#include "flarekit/Result.h"

namespace flarekit {

//! Bounds checked while a document is parsed, before its tree can grow past them.
struct JsonLimits {
    //! 64 levels: the deepest shipped format (scene objects' vertices) nests 4; 64 keeps every
    //! recursive walk of the tree (nlohmann's own dump, comparisons) far from the stack's end.
    std::size_t maxDepth = 64;
    std::size_t maxValues = std::size_t(1) << 20;  //!< every key and value counts one
    std::string what = "a preset";                 //!< what the limit is for, for the message
};

//! Parses text; a syntax error becomes "source: invalid JSON: parse error at line L, column C:
//! ...", a number past double's range "source: field: expected a finite number, got 1e999".
Result<nlohmann::json> parseJsonText(const std::string& text, const std::string& source,
                                     const JsonLimits& limits = {});
//! The value as JSON text, cut to 60 characters: what an error message shows after "got".
//! A long value is never dumped whole: the dump stops once it passes 60 characters.
std::string jsonExcerpt(const nlohmann::json& value);
//! The whole file, or an Io error naming it; files over maxBytes are refused unread.
Result<std::string> readTextFile(const std::string& path,
                                 std::uintmax_t maxBytes = std::uintmax_t(16) << 20);

}  // namespace flarekit
