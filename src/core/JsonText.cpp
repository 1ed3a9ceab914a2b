// SPDX-License-Identifier: Apache-2.0
#include "core/JsonText.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "flarekit/Limits.h"

namespace flarekit {

namespace {

using json = nlohmann::json;

//! Where the parser is, kept by the parse callback: the path of keys and indices down to the
//! value being read, so that a number overflow is reported at its field.
struct ParsePath {
    struct Frame {
        bool array = false;
        std::size_t index = 0;
        std::string key;
    };
    std::vector<Frame> frames;
    std::size_t values = 0;

    //! The path, cut to 60 characters (a deep one is only brackets).
    std::string text() const { return excerpt(fullText(), 60); }
    std::string fullText() const {
        std::string at;
        for (const Frame& f : frames) {
            if (f.array) {
                at += "[" + std::to_string(f.index) + "]";
            } else if (!f.key.empty()) {
                at += (at.empty() ? "" : ".") + excerpt(f.key, 60);
            }
        }
        return at;
    }
    void childDone() {
        if (!frames.empty() && frames.back().array) ++frames.back().index;
    }
};

//! Thrown from the parse callback to stop parsing, carrying the message.
struct ParseStop {
    std::string message;
};

//! "... last read: '<token>'" with the token cut: a hostile file can make it megabytes long.
std::string cutParseMessage(const std::string& what) {
    const auto pos = what.find("parse error");
    std::string text = pos == std::string::npos ? what : what.substr(pos);
    const std::string marker = "last read: '";
    const auto token = text.find(marker);
    if (token == std::string::npos) return excerpt(text, 300);
    const auto start = token + marker.size();
    const auto end = text.rfind('\'');
    const std::string read = end > start ? text.substr(start, end - start) : text.substr(start);
    return excerpt(text.substr(0, start), 240) + excerpt(read, 60) + "'";
}

}  // namespace

Result<nlohmann::json> parseJsonText(const std::string& text, const std::string& source,
                                     const JsonLimits& limits) {
    ParsePath path;
    // A parsed value costs about 64 bytes in nlohmann's tree (16 for the node, the vector or map
    // slot and allocation overhead around it); the tree is refused once that passes the budget.
    const std::size_t maxValues = std::min<std::size_t>(
        limits.maxValues, std::size_t(double(resourceLimits().maxMemoryBytes) / 64.0));
    const json::parser_callback_t track = [&](int, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start:
            case json::parse_event_t::array_start:
                if (path.frames.size() >= limits.maxDepth) {
                    throw ParseStop{source + ": " +
                                    (path.frames.empty() ? "(top level)" : path.text()) +
                                    ": expected JSON nested at most " +
                                    std::to_string(limits.maxDepth) + " levels deep"};
                }
                path.frames.push_back({event == json::parse_event_t::array_start, 0, {}});
                break;
            case json::parse_event_t::key:
                if (!path.frames.empty()) path.frames.back().key = parsed.get<std::string>();
                break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                if (!path.frames.empty()) path.frames.pop_back();
                path.childDone();
                break;
            case json::parse_event_t::value:
                path.childDone();
                break;
        }
        if (++path.values > maxValues) {
            throw ParseStop{source + ": " + (path.frames.empty() ? "(top level)" : path.text()) +
                            ": expected at most " + std::to_string(maxValues) + " JSON values (" +
                            limits.what + ")"};
        }
        return true;
    };
    try {
        return json::parse(text, track);
    } catch (const ParseStop& stop) {
        return invalidInput(stop.message);
    } catch (const json::parse_error& e) {
        return invalidInput(source + ": invalid JSON: " + cutParseMessage(e.what()));
    } catch (const json::out_of_range& e) {
        // 406: "number overflow parsing '1e999'": bad input at the field being read.
        std::string what = e.what();
        const auto quote = what.find('\'');
        std::string number = quote == std::string::npos ? std::string("a number out of range")
                                                        : what.substr(quote + 1);
        if (!number.empty() && number.back() == '\'') number.pop_back();
        return invalidInput(source + ": " + (path.frames.empty() ? "(top level)" : path.text()) +
                            ": expected a finite number, got " + excerpt(number, 60));
    } catch (const json::exception& e) {
        return invalidInput(source + ": invalid JSON: " + excerpt(e.what(), 200));
    }
}

namespace {
//! A string as JSON text; bytes that are not UTF-8 (a file may hold any) become U+FFFD instead
//! of making nlohmann throw.
std::string dumpText(const std::string& text) {
    return json(text).dump(-1, ' ', false, json::error_handler_t::replace);
}

//! nlohmann's compact dump, stopped once `out` is longer than `max`: a huge value costs only
//! what is shown. Recursion is bounded by the parse's depth limit.
void dumpUpTo(const json& v, std::string& out, std::size_t max) {
    if (out.size() > max) return;
    if (v.is_array()) {
        out += '[';
        bool first = true;
        for (const json& e : v) {
            if (out.size() > max) return;
            if (!first) out += ',';
            first = false;
            dumpUpTo(e, out, max);
        }
        out += ']';
    } else if (v.is_object()) {
        out += '{';
        bool first = true;
        for (const auto& [key, e] : v.items()) {
            if (out.size() > max) return;
            if (!first) out += ',';
            first = false;
            out += dumpText(excerpt(key, max)) + ':';
            dumpUpTo(e, out, max);
        }
        out += '}';
    } else if (v.is_string()) {
        out += dumpText(excerpt(v.get_ref<const std::string&>(), max + 4));
    } else {
        out += v.dump();
    }
}
}  // namespace

std::string jsonExcerpt(const nlohmann::json& value) {
    std::string text;
    dumpUpTo(value, text, 60);
    return excerpt(text, 60);
}

Result<std::string> readTextFile(const std::string& path, std::uintmax_t maxBytes) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return ioError(path + ": cannot read: no such file");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > maxBytes) {
        return invalidInput(path + ": " + formatBytes(double(size)) + ": expected at most " +
                            formatBytes(double(maxBytes)) + " for this kind of file");
    }
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) return ioError(path + ": cannot read");
    return text.str();
}

}  // namespace flarekit
