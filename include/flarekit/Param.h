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

//! A text member (a file, a file pattern, a channel or colour-space name), described once as a
//! numeric parameter is: its key and help feed the CLI's flag, the studio's field and the docs.
//! What the text must be is checked by the job that reads it (the file, the channel it names).
template <class Owner>
struct TextParam {
    std::string_view key;
    std::string Owner::*member = nullptr;
    std::string_view help;
};

//! `text<&OcclusionOptions::matte>("matte", "holdout matte ...")`.
template <auto Member>
constexpr TextParam<param_detail::OwnerOf<Member>> text(std::string_view key,
                                                        std::string_view help) {
    static_assert(std::is_same_v<param_detail::FieldOf<Member>, std::string>, "a text member");
    return {key, Member, help};
}

template <class Owner>
constexpr const Param<Owner>* findParam(std::span<const Param<Owner>> table, std::string_view key) {
    for (const Param<Owner>& p : table) {
        if (p.key == key) return &p;
    }
    return nullptr;
}

}  // namespace flarekit
