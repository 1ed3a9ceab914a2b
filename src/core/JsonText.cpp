#include "core/JsonText.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace flarekit {

Result<nlohmann::json> parseJsonText(const std::string& text, const std::string& source) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        const std::string what =
            e.what();  // "[json.exception.parse_error.101] parse error at line ..."
        const auto pos = what.find("parse error");
        return invalidInput(
            source + ": invalid JSON: " + (pos == std::string::npos ? what : what.substr(pos)));
    }
}

std::string jsonExcerpt(const nlohmann::json& value) {
    std::string text = value.dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}

Result<std::string> readTextFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return ioError(path + ": cannot read: no such file");
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) return ioError(path + ": cannot read");
    return text.str();
}

}  // namespace flarekit
