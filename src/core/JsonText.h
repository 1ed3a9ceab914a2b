// JSON input shared by presets and scenes: parse errors and value excerpts in the one-line
// "file: field: ..." style, and reading a text file. Included only by the JSON readers, so
// nlohmann-json stays out of every other translation unit.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "flarekit/Result.h"

namespace flarekit {

//! Parses text; a syntax error becomes "source: invalid JSON: parse error at line L, column C:
//! ...".
Result<nlohmann::json> parseJsonText(const std::string& text, const std::string& source);
//! The value as JSON text, cut to 60 characters: what an error message shows after "got".
std::string jsonExcerpt(const nlohmann::json& value);
//! The whole file, or an Io error naming it.
Result<std::string> readTextFile(const std::string& path);

}  // namespace flarekit
