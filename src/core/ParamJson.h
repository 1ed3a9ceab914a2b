// SPDX-License-Identifier: Apache-2.0
// The one JSON reader of parameter tables (flarekit/Param.h): converts each key of a JSON
// object through its description, reports unknown keys with the list of known ones, and words
// every error "source: field: expected ..., got <excerpt>".
#pragma once

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "core/JsonText.h"
#include "flarekit/Param.h"
#include "flarekit/ParamText.h"

namespace flarekit {

//! Where a reader is: the file (for messages) and the field path so far ("element[3]").
class JsonPlace {
  public:
    JsonPlace(std::string source, std::string at = {})
        : m_source(std::move(source)), m_at(std::move(at)) {}
    //! The key cut to 60 characters: keys come from the input and may be megabytes long.
    JsonPlace operator/(std::string_view key) const {
        const std::string k = excerpt(key, 60);
        return {m_source, m_at.empty() ? k : m_at + "." + k};
    }
    JsonPlace index(std::size_t i) const {
        return {m_source, m_at + "[" + std::to_string(i) + "]"};
    }
    const std::string& at() const { return m_at; }
    const std::string& source() const { return m_source; }
    Error fail(const std::string& what) const {
        return invalidInput(m_source + ": " + (m_at.empty() ? "(top level)" : m_at) + ": " + what);
    }

  private:
    std::string m_source, m_at;
};

//! A JSON value converted through a parameter's description, or the error naming `place`.
template <class Owner>
Result<ParamValue> readParamValue(const Param<Owner>& p, const nlohmann::json& v,
                                  const JsonPlace& place) {
    const auto bad = [&] {
        return place.fail("expected " + expectedText(p) + ", got " + jsonExcerpt(v));
    };
    const auto number = [&](const nlohmann::json& x) -> std::optional<double> {
        if (!x.is_number()) return std::nullopt;
        const double d = x.get<double>();
        if (!numberFits(p, d)) return std::nullopt;
        return d;
    };
    //! The three components of a colour or vector, each through `number`.
    const auto triple = [&](double c[3]) {
        if (!v.is_array() || v.size() != 3) return false;
        for (std::size_t i = 0; i < 3; ++i) {
            const auto d = number(v[i]);
            if (!d) return false;
            c[i] = *d;
        }
        return true;
    };
    ParamValue out;
    double c[3];
    switch (p.type) {
        case ParamType::Number:
        case ParamType::Integer:
        case ParamType::Seed: {
            const auto d = number(v);
            if (!d) return bad();
            out.number = *d;
            return out;
        }
        case ParamType::Color:
        case ParamType::OptionalColor:
            if (!triple(c)) return bad();
            out.color = {float(c[0]), float(c[1]), float(c[2])};
            return out;
        case ParamType::Vector:
            if (!triple(c)) return bad();
            out.vector = {c[0], c[1], c[2]};
            return out;
        case ParamType::Bool:
            if (!v.is_boolean()) return bad();
            out.number = v.get<bool>() ? 1 : 0;
            return out;
        case ParamType::Choice:
            if (v.is_string()) {
                for (std::size_t i = 0; i < p.choices.size(); ++i) {
                    if (v.get<std::string>() == p.choices[i]) {
                        out.number = double(i);
                        return out;
                    }
                }
            }
            return bad();
    }
    return bad();
}

//! Every key of the object `v` into `owner` through `table`. Keys in `skip` are left to the
//! caller (listed among the known ones); keys whose parameter does not apply (`mask`) are
//! unknown. `what`, when given, words the unknown-key error "unknown key for a <what>".
template <class Owner>
std::optional<Error> readParams(const nlohmann::json& v, std::span<const Param<Owner>> table,
                                Owner& owner, const JsonPlace& place,
                                std::initializer_list<std::string_view> skip = {},
                                std::uint32_t mask = ~0u, std::string_view what = {}) {
    if (!v.is_object()) return place.fail("expected an object, got " + jsonExcerpt(v));
    for (const auto& [key, value] : v.items()) {
        bool skipped = false;
        for (std::string_view s : skip) skipped = skipped || s == key;
        if (skipped) continue;
        const Param<Owner>* p = findParam(table, key);
        if (!p || !(p->appliesTo & mask)) {
            std::string known;
            for (std::string_view s : skip) known += (known.empty() ? "" : ", ") + std::string(s);
            for (const Param<Owner>& q : table) {
                if (q.appliesTo & mask) known += (known.empty() ? "" : ", ") + std::string(q.key);
            }
            const std::string forWhat = what.empty() ? "" : " for a " + std::string(what);
            return (place / key)
                .fail("unknown key" + forWhat + " (expected one of: " + known + ")");
        }
        auto read = readParamValue(*p, value, place / key);
        if (!read) return read.error();
        p->set(owner, *read);
    }
    for (const Param<Owner>& p : table) {
        if (p.required && (p.appliesTo & mask) && !v.contains(std::string(p.key))) {
            return (place / p.key).fail("missing; expected " + expectedText(p));
        }
    }
    return std::nullopt;
}

//! A float member's value as the shortest decimal that reads back to the same float (0.1, not
//! 0.10000000149011612).
inline double shortestFloat(double x) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, float(x)).ptr;
    *end = '\0';
    return std::strtod(text, nullptr);
}

//! The JSON value of a parameter: the writer's twin of readParamValue.
template <class Owner>
nlohmann::json paramJsonValue(const Param<Owner>& p, const ParamValue& v) {
    const auto number = [&](double x) { return p.singlePrecision ? shortestFloat(x) : x; };
    switch (p.type) {
        case ParamType::Number:
            return number(v.number);
        case ParamType::Integer:
            return int(v.number);
        case ParamType::Seed:
            return std::uint32_t(v.number);
        case ParamType::Bool:
            return v.number != 0;
        case ParamType::Color:
        case ParamType::OptionalColor:
            return {number(v.color[0]), number(v.color[1]), number(v.color[2])};
        case ParamType::Vector:
            return {v.vector.x, v.vector.y, v.vector.z};
        case ParamType::Choice:
            return std::string(p.choices[std::size_t(v.number)]);
    }
    return nullptr;
}

//! The keys of `table` (those `mask` applies to) where `owner` differs from `defaults`, as a
//! JSON object that readParams reads back to the same values.
template <class Owner>
nlohmann::json writeParams(const Owner& owner, std::span<const Param<Owner>> table,
                           const Owner& defaults, std::uint32_t mask = ~0u) {
    nlohmann::json out = nlohmann::json::object();
    for (const Param<Owner>& p : table) {
        if (!(p.appliesTo & mask)) continue;
        const ParamValue v = p.get(owner), d = p.get(defaults);
        if (p.type == ParamType::OptionalColor && !v.hasColor) continue;
        const bool same = v.number == d.number && v.color == d.color && v.hasColor == d.hasColor &&
                          v.vector.x == d.vector.x && v.vector.y == d.vector.y &&
                          v.vector.z == d.vector.z;
        if (!same || p.required) out[std::string(p.key)] = paramJsonValue(p, v);
    }
    return out;
}

}  // namespace flarekit
