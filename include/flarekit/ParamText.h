// SPDX-License-Identifier: Apache-2.0
// The words of a parameter description (flarekit/Param.h): "expected a number in [0, 1], got 2"
// for validation, range and value texts for a CLI's help, Markdown rows for the docs. Apart from
// Param.h so that a header declaring a table does not carry the text machinery; what validates
// or documents parameters includes this.
#pragma once

#include <sstream>

#include "flarekit/Param.h"

namespace flarekit {

//! Appends the parts (strings, string views, literals) in order. (Also keeps GCC 12's
//! -Wrestrict false positive on `"literal" + std::string` out of every file that includes this.)
template <class... Parts>
std::string joinText(const Parts&... parts) {
    std::string out;
    (out.append(parts), ...);
    return out;
}

//! A number as the docs and messages print it: integers in full (seeds), others in 6 digits.
inline std::string formatParamNumber(double x) {
    if (x == std::floor(x) && std::abs(x) < 1e15) return std::to_string(static_cast<long long>(x));
    std::ostringstream os;
    os << x;
    return os.str();
}

inline std::string formatParamRange(double lo, double hi) {
    return joinText("[", formatParamNumber(lo), ", ", formatParamNumber(hi), "]");
}

//! What a message says was expected: "a number in [0, 4]", "one of \"add\", \"screen\"", ...
template <class Owner>
std::string expectedText(const Param<Owner>& p) {
    std::string range = formatParamRange(p.min, p.max);
    if (p.openMin) range[0] = '(';
    const bool unbounded = p.max >= kParamUnbounded;
    auto quoted = [&](std::size_t i) { return joinText("\"", p.choices[i], "\""); };
    switch (p.type) {
        case ParamType::Number:
            if (unbounded && p.min == 0)
                return p.openMin ? "a positive number" : "a non-negative number";
            return joinText("a number in ", range);
        case ParamType::Vector:
            if (unbounded && p.min == 0 && !p.openMin) return "an array of 3 non-negative numbers";
            if (unbounded && p.min <= -kParamUnbounded) return "an array of 3 numbers";
            return joinText("an array of 3 numbers in ", range);
        case ParamType::Integer:
        case ParamType::Seed:
            if (!p.only.empty()) {
                std::string list;
                for (std::size_t i = 0; i < p.only.size(); ++i) {
                    list += (i ? ", " : "") + std::to_string(p.only[i]);
                }
                return joinText("one of ", list);
            }
            return joinText("an integer in ", range);
        case ParamType::Bool:
            return "true or false";
        case ParamType::Color:
        case ParamType::OptionalColor:
            return joinText("an array of 3 numbers in ", range);
        case ParamType::Choice: {
            if (p.choices.size() == 2) return joinText(quoted(0), " or ", quoted(1));
            std::string list = "one of ";
            for (std::size_t i = 0; i < p.choices.size(); ++i) list += (i ? ", " : "") + quoted(i);
            return list;
        }
    }
    return {};
}

//! Whether a number fits the parameter (type, range, finiteness, integrality, `only`).
template <class Owner>
bool numberFits(const Param<Owner>& p, double x) {
    if (!std::isfinite(x)) return false;
    if (p.singlePrecision) {
        if (float(x) < float(p.min) || float(x) > float(p.max)) return false;
        if (p.openMin && float(x) == float(p.min)) return false;
    } else if (x < p.min || x > p.max || (p.openMin && x == p.min)) {
        return false;
    }
    if (p.type == ParamType::Number || p.type == ParamType::Color ||
        p.type == ParamType::OptionalColor || p.type == ParamType::Vector) {
        return true;
    }
    if (x != std::floor(x)) return false;
    if (p.only.empty()) return true;
    for (int v : p.only) {
        if (double(v) == x) return true;
    }
    return false;
}

template <class Owner>
bool valueFits(const Param<Owner>& p, const ParamValue& v) {
    if (p.type == ParamType::Color || p.type == ParamType::OptionalColor) {
        if (!v.hasColor) return p.type == ParamType::OptionalColor;
        for (float c : v.color) {
            if (!numberFits(p, double(c))) return false;
        }
        return true;
    }
    if (p.type == ParamType::Vector) {
        return numberFits(p, v.vector.x) && numberFits(p, v.vector.y) && numberFits(p, v.vector.z);
    }
    if (p.type == ParamType::Bool) return v.number == 0 || v.number == 1;
    return numberFits(p, v.number);
}

//! The value as the docs print it: 0.5, [1, 0.8, 0.55], "aces", true, (derived).
template <class Owner>
std::string valueText(const Param<Owner>& p, const ParamValue& v) {
    switch (p.type) {
        case ParamType::Color:
        case ParamType::OptionalColor:
            if (!v.hasColor) return "";
            return joinText("[", formatParamNumber(v.color[0]), ", ", formatParamNumber(v.color[1]),
                            ", ", formatParamNumber(v.color[2]), "]");
        case ParamType::Vector:
            return joinText("[", formatParamNumber(v.vector.x), ", ", formatParamNumber(v.vector.y),
                            ", ", formatParamNumber(v.vector.z), "]");
        case ParamType::Bool:
            return v.number != 0 ? "true" : "false";
        case ParamType::Choice: {
            const auto i = std::size_t(v.number);
            return i < p.choices.size() ? joinText("`", p.choices[i], "`") : "?";
        }
        default:
            return formatParamNumber(v.number);
    }
}

//! The range column of the docs: "[0, 4]", "3 x [0, 64]", "`add`, `screen`", "true, false".
template <class Owner>
std::string rangeText(const Param<Owner>& p) {
    std::string range = formatParamRange(p.min, p.max);
    if (p.openMin) range[0] = '(';
    switch (p.type) {
        case ParamType::Color:
        case ParamType::OptionalColor:
        case ParamType::Vector:
            return joinText("3 x ", range);
        case ParamType::Bool:
            return "true, false";
        case ParamType::Choice: {
            std::string list;
            for (std::size_t i = 0; i < p.choices.size(); ++i) {
                list += joinText(i ? ", `" : "`", p.choices[i], "`");
            }
            return list;
        }
        default:
            if (!p.only.empty()) {
                std::string list;
                for (std::size_t i = 0; i < p.only.size(); ++i) {
                    list += (i ? ", " : "") + std::to_string(p.only[i]);
                }
                return list;
            }
            return range;
    }
}

//! Checks every parameter of `owner` that applies (`mask`) against its description: the one
//! validator behind both JSON input and parameters built in code. Errors read
//! "<prefix><key>: expected ..., got ...".
template <class Owner>
Status validateParams(const Owner& owner, std::span<const Param<Owner>> table,
                      const std::string& prefix, std::uint32_t mask = ~0u) {
    for (const Param<Owner>& p : table) {
        if (!(p.appliesTo & mask)) continue;
        const ParamValue v = p.get(owner);
        if (valueFits(p, v)) continue;
        return invalidInput(
            joinText(prefix, p.key, ": expected ", expectedText(p), ", got ", valueText(p, v)));
    }
    return Ok{};
}

//! One Markdown row per parameter: | <before> `key` | <after> [default |] range | unit | help |.
//! `before(p)` and `after(p)` return extra columns, each ending in " | " (a section name, the
//! element types); without `defaults` (per-type defaults, documented apart) there is no
//! default column.
template <class Owner, class Before, class After>
std::string markdownRows(std::span<const Param<Owner>> table, const Owner* defaults,
                         const Before& before, const After& after) {
    std::string out;
    for (const Param<Owner>& p : table) {
        out += joinText("| ", before(p), "`", p.key, "` | ", after(p));
        if (defaults) out += joinText(valueText(p, p.get(*defaults)), " | ");
        out += joinText(rangeText(p), " | ", p.unit, " | ", p.help, " |\n");
    }
    return out;
}

}  // namespace flarekit
