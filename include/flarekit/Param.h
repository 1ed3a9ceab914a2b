// SPDX-License-Identifier: Apache-2.0
// One description per tunable parameter: JSON key (also the CLI flag's name), type, range or
// choices, unit and help, with the default read from the params struct itself. Every product
// reads the same description: the JSON readers (src/core/ParamJson.h), the validator that
// parameters built in code go through (validateParams), the CLI's flags (their range checks and
// help) and the Markdown tables in docs/. A table sits in the public header right after the
// struct it describes, e.g. kBrightParams after BrightParams.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

#include "flarekit/Result.h"
#include "flarekit/Vec3.h"

namespace flarekit {

using Rgb = std::array<float, 3>;  //!< linear-light RGB

enum class ParamType {
    Number,         //!< float or double
    Integer,        //!< int
    Seed,           //!< std::uint32_t
    Bool,           //!< true / false
    Color,          //!< Rgb, each component in [min, max]
    OptionalColor,  //!< std::optional<Rgb>: absent means "derived" (see the help)
    Choice,         //!< an enum (or bool) picked by name from `choices`, in value order
    Vector,         //!< Vec3 (double), each component in [min, max]: positions, directions
};

//! A bound past any sensible value: a range reaching it reads "a positive number" in messages.
inline constexpr double kParamUnbounded = 1e12;

//! A parameter's value in one shape for every type: number (Choice: the index, Bool: 0 or 1)
//! or colour (`hasColor` false: an absent optional colour).
struct ParamValue {
    double number = 0;
    Rgb color{};
    bool hasColor = true;
    Vec3 vector{};
};

template <class Owner>
struct Param {
    std::string_view key;
    ParamType type = ParamType::Number;
    double min = 0, max = 0;  //!< inclusive (per component for colours); unused for Bool, Choice
    std::string_view unit;
    std::string_view help;
    std::span<const std::string_view> choices;  //!< Choice: the names, index = value
    std::span<const int> only;                  //!< Integer: when set, the only values allowed
    std::uint32_t appliesTo = ~0u;              //!< owner-defined bits (element types); ~0 = always
    //! A float member (or Rgb): ranges compare in float, so 0.01 read into a float (0.0099999998)
    //! still meets a minimum of 0.01.
    bool singlePrecision = false;
    bool openMin = false;   //!< (min, max]: min itself is refused (a radius, a field of view)
    bool required = false;  //!< the JSON reader refuses an object without it
    ParamValue (*get)(const Owner&) = nullptr;
    void (*set)(Owner&, const ParamValue&) = nullptr;

    bool isNumeric() const {
        return type == ParamType::Number || type == ParamType::Integer || type == ParamType::Seed;
    }
};

namespace param_detail {

template <class M>
struct MemberOf;
template <class O, class T>
struct MemberOf<T O::*> {
    using Owner = O;
    using Type = T;
};
template <auto M>
using OwnerOf = typename MemberOf<decltype(M)>::Owner;
template <auto M>
using FieldOf = typename MemberOf<decltype(M)>::Type;

template <class T>
constexpr ParamType typeOf() {
    if constexpr (std::is_same_v<T, bool>)
        return ParamType::Bool;
    else if constexpr (std::is_floating_point_v<T>)
        return ParamType::Number;
    else if constexpr (std::is_same_v<T, std::uint32_t>)
        return ParamType::Seed;
    else if constexpr (std::is_integral_v<T>)
        return ParamType::Integer;
    else if constexpr (std::is_same_v<T, Rgb>)
        return ParamType::Color;
    else if constexpr (std::is_same_v<T, std::optional<Rgb>>)
        return ParamType::OptionalColor;
    else if constexpr (std::is_same_v<T, Vec3>)
        return ParamType::Vector;
    else {
        static_assert(std::is_enum_v<T>, "a parameter is a number, bool, colour, vector or enum");
        return ParamType::Choice;
    }
}

template <auto M>
ParamValue get(const OwnerOf<M>& owner) {
    using T = FieldOf<M>;
    const T& v = owner.*M;
    ParamValue out;
    if constexpr (std::is_same_v<T, Rgb>)
        out.color = v;
    else if constexpr (std::is_same_v<T, std::optional<Rgb>>) {
        out.color = v.value_or(Rgb{}), out.hasColor = v.has_value();
    } else if constexpr (std::is_same_v<T, Vec3>)
        out.vector = v;
    else
        out.number = double(v);
    return out;
}

template <auto M>
void set(OwnerOf<M>& owner, const ParamValue& value) {
    using T = FieldOf<M>;
    T& v = owner.*M;
    if constexpr (std::is_same_v<T, Rgb>)
        v = value.color;
    else if constexpr (std::is_same_v<T, std::optional<Rgb>>) {
        v = value.hasColor ? std::optional<Rgb>(value.color) : std::nullopt;
    } else if constexpr (std::is_same_v<T, Vec3>)
        v = value.vector;
    else if constexpr (std::is_same_v<T, bool>)
        v = value.number != 0;
    else if constexpr (std::is_enum_v<T>)
        v = T(int(value.number));
    else
        v = T(value.number);
}

//! The parts every factory sets: key, help, the member's type and its accessors.
template <auto Member>
constexpr Param<OwnerOf<Member>> base(std::string_view key, std::string_view help,
                                      std::uint32_t appliesTo) {
    using T = FieldOf<Member>;
    Param<OwnerOf<Member>> p;
    p.key = key, p.help = help, p.appliesTo = appliesTo;
    p.type = typeOf<T>();
    p.singlePrecision =
        std::is_same_v<T, float> || std::is_same_v<T, Rgb> || std::is_same_v<T, std::optional<Rgb>>;
    p.get = &get<Member>, p.set = &set<Member>;
    return p;
}

}  // namespace param_detail

//! A number, integer, seed, bool, colour or vector member: `param<&BloomParams::levels>("levels",
//! 2, 12, "mips", "downsample levels")`. The type comes from the member.
template <auto Member>
constexpr Param<param_detail::OwnerOf<Member>> param(std::string_view key, double min, double max,
                                                     std::string_view unit, std::string_view help,
                                                     std::uint32_t appliesTo = ~0u) {
    static_assert(!std::is_enum_v<param_detail::FieldOf<Member>>, "an enum member is a choice<>()");
    auto p = param_detail::base<Member>(key, help, appliesTo);
    p.min = min, p.max = max, p.unit = unit;
    return p;
}

//! An enum (or bool) member picked by name; names[i] is the value i.
template <auto Member>
constexpr Param<param_detail::OwnerOf<Member>> choice(std::string_view key,
                                                      std::span<const std::string_view> names,
                                                      std::string_view help,
                                                      std::uint32_t appliesTo = ~0u) {
    auto p = param_detail::base<Member>(key, help, appliesTo);
    p.type = ParamType::Choice, p.singlePrecision = false;
    p.min = 0, p.max = double(names.size()) - 1, p.choices = names;
    return p;
}

//! An integer member that takes only the listed values (MSAA sample counts).
template <auto Member>
constexpr Param<param_detail::OwnerOf<Member>> oneOf(std::string_view key,
                                                     std::span<const int> values,
                                                     std::string_view unit, std::string_view help) {
    Param<param_detail::OwnerOf<Member>> p =
        param<Member>(key, double(values.front()), double(values.back()), unit, help);
    p.only = values;
    return p;
}

//! The same parameter, required in JSON objects.
template <class Owner>
constexpr Param<Owner> required(Param<Owner> p) {
    p.required = true;
    return p;
}

//! The same parameter with its minimum excluded: (min, max].
template <class Owner>
constexpr Param<Owner> aboveMin(Param<Owner> p) {
    p.openMin = true;
    return p;
}

template <class Owner>
const Param<Owner>* findParam(std::span<const Param<Owner>> table, std::string_view key) {
    for (const Param<Owner>& p : table) {
        if (p.key == key) return &p;
    }
    return nullptr;
}

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
