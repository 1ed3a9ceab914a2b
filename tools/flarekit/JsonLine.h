// SPDX-License-Identifier: Apache-2.0
// One JSON object on one line, the way `visibility --json` and `psp --json` print it (a
// contract: key order, ", " and ": " separators, fixed decimals). Strings are escaped by
// nlohmann-json, so a path or name with quotes still gives valid JSON.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

namespace flarekit::cli {

class JsonLine {
  public:
    JsonLine& text(const char* key, const std::string& value) {
        return raw(key, nlohmann::json(value).dump(-1, ' ', false,
                                                   nlohmann::json::error_handler_t::replace));
    }
    JsonLine& number(const char* key, double value, int decimals) {
        char s[64];
        std::snprintf(s, sizeof s, "%.*f", decimals, value);
        return raw(key, s);
    }
    JsonLine& integer(const char* key, long long value) { return raw(key, std::to_string(value)); }
    JsonLine& boolean(const char* key, bool value) { return raw(key, value ? "true" : "false"); }
    JsonLine& null(const char* key) { return raw(key, "null"); }
    //! A value already in JSON (a nested object or an array of them).
    JsonLine& json(const char* key, const std::string& value) { return raw(key, value); }
    std::string str() const { return "{" + m_body + "}"; }

  private:
    JsonLine& raw(const char* key, const std::string& value) {
        m_body +=
            (m_body.empty() ? "" : ", ") +
            nlohmann::json(key).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) +
            ": " + value;
        return *this;
    }
    std::string m_body;
};

}  // namespace flarekit::cli
