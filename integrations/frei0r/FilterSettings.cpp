// SPDX-License-Identifier: Apache-2.0
#include "FilterSettings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace flarekit::frei0r {

void setNumber(FilterSettings& settings, const Param<FilterSettings>& param, double value) {
    if (std::isnan(value)) return;
    ParamValue v;
    v.number = std::clamp(value, param.min, param.max);
    param.set(settings, v);
}

Status setChoice(FilterSettings& settings, const Param<FilterSettings>& param,
                 std::string_view value) {
    std::string names;
    for (std::size_t i = 0; i < param.choices.size(); ++i) {
        if (param.choices[i] == value) {
            ParamValue v;
            v.number = double(i);
            param.set(settings, v);
            return Ok{};
        }
        names += std::string(i ? ", " : "") + std::string(param.choices[i]);
    }
    return invalidInput(std::string(param.key) + ": expected one of " + names + ", got '" +
                        std::string(value) + "'");
}

std::string choiceName(const FilterSettings& settings, const Param<FilterSettings>& param) {
    const auto i = std::size_t(param.get(settings).number);
    return i < param.choices.size() ? std::string(param.choices[i]) : std::string();
}

namespace {

//! A YAML double-quoted scalar.
std::string quoted(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

}  // namespace

std::string mltMetadata() {
    const FilterSettings defaults;
    std::string y =
        "# The MLT service metadata of flarekit's frei0r filter (made by "
        "flarekit-frei0r-metadata from\n"
        "# the plug-in's own parameter table): Kdenlive and Shotcut list the effect from it.\n"
        "schema_version: 0.3\n"
        "type: filter\n"
        "identifier: frei0r.flarekit\n"
        "title: flarekit Lens Flare\n"
        "version: 1\n"
        "copyright: flarekit contributors\n"
        "license: Apache-2.0\n"
        "language: en\n"
        "tags:\n"
        "  - Video\n"
        "description: >\n"
        "  Lens flares from the lights of the clip: a sprite preset, the post-process chain or a\n"
        "  lens prescription's traced ghosts, in linear light, the light found, followed through\n"
        "  the clip or placed by keyframes.\n"
        "parameters:\n";
    for (const FilterParam& p : kFilterParams) {
        y += "  - identifier: " + std::string(p.name) + "\n";
        y += "    title: " + quoted(p.name) + "\n";
        if (p.text) {
            y += "    type: string\n";
            y += "    default: " + quoted(defaults.*(p.text->member)) + "\n";
        } else if (p.number->type == ParamType::Choice) {
            y += "    type: string\n";
            y += "    default: " + quoted(choiceName(defaults, *p.number)) + "\n";
            y += "    values:\n";
            for (std::string_view c : p.number->choices) y += "      - " + std::string(c) + "\n";
        } else {
            y += "    type: float\n";
            y += "    minimum: " + number(p.number->min) + "\n";
            y += "    maximum: " + number(p.number->max) + "\n";
            y += "    default: " + number(p.number->get(defaults).number) + "\n";
            if (!p.number->unit.empty()) y += "    unit: " + quoted(p.number->unit) + "\n";
            y += "    mutable: yes\n    animation: yes\n";
        }
        y += "    description: " + quoted(p.help()) + "\n";
    }
    return y;
}

std::string markdownTable() {
    const FilterSettings defaults;
    std::string t =
        "| # | name | type | default | range | what it does |\n|---|---|---|---|---|---|\n";
    int index = 0;
    for (const FilterParam& p : kFilterParams) {
        std::string type = "string", value, range;
        if (p.text) {
            value = defaults.*(p.text->member);
            value = value.empty() ? "(empty)" : "`" + value + "`";
        } else if (p.number->type == ParamType::Choice) {
            value = "`" + choiceName(defaults, *p.number) + "`";
            for (std::string_view c : p.number->choices)
                range += (range.empty() ? "" : ", ") + std::string("`") + std::string(c) + "`";
        } else {
            type = "double";
            value = number(p.number->get(defaults).number);
            range = number(p.number->min) + " to " + number(p.number->max);
            if (!p.number->unit.empty()) range += " " + std::string(p.number->unit);
        }
        t += "| " + std::to_string(index++) + " | `" + std::string(p.name) + "` | " + type + " | " +
             value + " | " + range + " | " + std::string(p.help()) + " |\n";
    }
    return t;
}

}  // namespace flarekit::frei0r
