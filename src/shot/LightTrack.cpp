// SPDX-License-Identifier: Apache-2.0
// A light's position keyed per frame: CSV or JSON in, linear interpolation between keys, the
// end keys held outside them (as a compositor's tracker hands a track to its flare).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/JsonText.h"
#include "flarekit/Shot.h"

namespace flarekit {

namespace {
//! Trailing spaces, tabs and a CR (a track saved on Windows) off both ends.
std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

std::vector<std::string_view> splitCommas(std::string_view line) {
    std::vector<std::string_view> fields;
    for (;;) {
        const auto comma = line.find(',');
        fields.push_back(trimmed(line.substr(0, comma)));
        if (comma == std::string_view::npos) return fields;
        line.remove_prefix(comma + 1);
    }
}

//! One key's checks, shared by both formats: `where` is "line 4" or "keys[3]".
Status checkKey(const LightKey& key, const LightKey* previous, const std::string& where) {
    const std::pair<const char*, double> fields[] = {
        {"frame", key.frame}, {"x", key.x}, {"y", key.y}, {"intensity", key.intensity}};
    for (const auto& [name, value] : fields)
        if (!std::isfinite(value))
            return invalidInput(where + ": " + name + ": expected a finite number");
    if (key.intensity < 0)
        return invalidInput(where + ": intensity: expected a number >= 0, got " +
                            std::to_string(key.intensity));
    if (previous && !(key.frame > previous->frame)) {
        char message[160];
        std::snprintf(message, sizeof message,
                      ": frame %g does not come after frame %g: keys must be sorted by frame, "
                      "each frame once",
                      key.frame, previous->frame);
        return invalidInput(where + message);
    }
    return Ok{};
}

Result<LightTrack> parseCsv(const std::string& text, const std::string& source) {
    std::istringstream in(text);
    std::string line;
    int lineNumber = 0;
    LightTrack track;
    bool header = false;
    while (std::getline(in, line)) {
        ++lineNumber;
        const std::string_view row = trimmed(line);
        if (row.empty()) continue;
        const std::string where = source + ": line " + std::to_string(lineNumber);
        if (!header) {
            if (row == "frame,x,y,intensity") {
                track.hasIntensity = true;
            } else if (row != "frame,x,y") {
                return invalidInput(where + ": expected the header frame,x,y or " +
                                    "frame,x,y,intensity, got '" + std::string(row.substr(0, 60)) +
                                    "'");
            }
            header = true;
            continue;
        }
        const std::vector<std::string_view> fields = splitCommas(row);
        const std::size_t expected = track.hasIntensity ? 4 : 3;
        if (fields.size() != expected)
            return invalidInput(where + ": expected " + std::to_string(expected) +
                                " comma-separated numbers, got " + std::to_string(fields.size()));
        double values[4] = {0, 0, 0, 1};
        static constexpr const char* kNames[] = {"frame", "x", "y", "intensity"};
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const std::string_view f = fields[i];
            auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), values[i]);
            if (f.empty() || ec != std::errc() || ptr != f.data() + f.size())
                return invalidInput(where + ": " + kNames[i] + ": expected a number, got '" +
                                    std::string(f.substr(0, 60)) + "'");
        }
        const LightKey key{values[0], values[1], values[2], values[3]};
        if (Status s = checkKey(key, track.keys.empty() ? nullptr : &track.keys.back(), where); !s)
            return s.error();
        track.keys.push_back(key);
    }
    if (!header) return invalidInput(source + ": empty track (expected the header frame,x,y)");
    return track;
}

Result<LightTrack> parseJson(const std::string& text, const std::string& source) {
    JsonLimits limits;
    limits.what = "a light track";
    auto json = parseJsonText(text, source, limits);
    if (!json) return json.error();
    const nlohmann::json* keys = &*json;
    if (json->is_object()) {
        if (!json->contains("keys") || json->size() != 1)
            return invalidInput(source + ": expected {\"keys\": [...]} or an array of keys");
        keys = &(*json)["keys"];
    }
    if (!keys->is_array()) return invalidInput(source + ": keys: expected an array");
    LightTrack track;
    for (std::size_t i = 0; i < keys->size(); ++i) {
        const nlohmann::json& k = (*keys)[i];
        const std::string where = source + ": keys[" + std::to_string(i) + "]";
        if (!k.is_object()) return invalidInput(where + ": expected an object");
        LightKey key;
        for (const auto& [name, value] : k.items()) {
            double* field = name == "frame"       ? &key.frame
                            : name == "x"         ? &key.x
                            : name == "y"         ? &key.y
                            : name == "intensity" ? &key.intensity
                                                  : nullptr;
            if (!field)
                return invalidInput(where + ": unknown key '" + name.substr(0, 60) +
                                    "' (known: frame, x, y, intensity)");
            if (!value.is_number())
                return invalidInput(where + "." + name + ": expected a number, got " +
                                    jsonExcerpt(value));
            *field = value.get<double>();
        }
        for (const char* required : {"frame", "x", "y"})
            if (!k.contains(required))
                return invalidInput(where + ": missing \"" + required + "\"");
        track.hasIntensity = track.hasIntensity || k.contains("intensity");
        if (Status s = checkKey(key, track.keys.empty() ? nullptr : &track.keys.back(), where); !s)
            return s.error();
        track.keys.push_back(key);
    }
    return track;
}
}  // namespace

LightTrack::Sample LightTrack::at(double frame) const {
    if (keys.empty()) return {};
    auto sample = [](const LightKey& k, bool held) {
        return Sample{{float(k.x), float(k.y)}, float(k.intensity), held};
    };
    if (frame <= keys.front().frame) return sample(keys.front(), frame < keys.front().frame);
    if (frame >= keys.back().frame) return sample(keys.back(), frame > keys.back().frame);
    std::size_t i = 1;
    while (keys[i].frame < frame) ++i;
    const LightKey &a = keys[i - 1], &b = keys[i];
    const double t = (frame - a.frame) / (b.frame - a.frame);
    auto mix = [t](double u, double v) { return u + (v - u) * t; };
    return {
        {float(mix(a.x, b.x)), float(mix(a.y, b.y))}, float(mix(a.intensity, b.intensity)), false};
}

Result<LightTrack> parseLightTrack(const std::string& text, const std::string& source) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    Result<LightTrack> track =
        first != std::string::npos && (text[first] == '{' || text[first] == '[')
            ? parseJson(text, source)
            : parseCsv(text, source);
    if (track && track->keys.empty()) return invalidInput(source + ": the track has no keys");
    return track;
}

Result<LightTrack> loadLightTrack(const std::string& path) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    return parseLightTrack(*text, path);
}

std::string lightTrackCsv(const LightTrack& track) {
    std::string out = track.hasIntensity ? "frame,x,y,intensity\n" : "frame,x,y\n";
    char line[160];
    for (const LightKey& k : track.keys) {
        // %.9g: a float position written and read back is the same float.
        if (track.hasIntensity)
            std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g\n", k.frame, k.x, k.y,
                          k.intensity);
        else
            std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g\n", k.frame, k.x, k.y);
        out += line;
    }
    return out;
}

}  // namespace flarekit
