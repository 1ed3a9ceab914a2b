// SPDX-License-Identifier: Apache-2.0
// Python keywords through the parameter tables (flarekit/Param.h): a keyword is a table's key,
// its value is checked against the same range the CLI's flag and the JSON reader check, and
// each function's docstring lists its tables' keys with range, unit, default and help.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "flarekit/Param.h"
#include "flarekit/ParamText.h"

namespace flarekit::python {

namespace py = pybind11;

//! A table key as a Python keyword: "light-threshold" is light_threshold.
inline std::string keywordName(std::string_view key) {
    std::string name(key);
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

//! The library's message or help with its CLI flags in Python's spelling (Convert.h).
std::string pythonSpelling(const std::string& message);

//! One keyword's value as a table parameter: numbers (bool counts as a number only for Bool),
//! a choice by its name, a colour or vector as three numbers. ValueError "key: expected ...,
//! got ..." otherwise.
template <class Owner>
void setKeyword(const Param<Owner>& p, const py::handle& value, Owner& owner) {
    const auto bad = [&] {
        throw py::value_error(keywordName(p.key) + ": expected " + expectedText(p) + ", got " +
                              std::string(py::repr(value)));
    };
    ParamValue v;
    const auto number = [&](const py::handle& x) {
        if (py::isinstance<py::bool_>(x) && p.type != ParamType::Bool) bad();
        if (!py::isinstance<py::int_>(x) && !py::isinstance<py::float_>(x) &&
            !py::isinstance<py::bool_>(x))
            bad();
        const double d = x.cast<double>();
        if (p.type != ParamType::Bool && !numberFits(p, d)) bad();
        return d;
    };
    switch (p.type) {
        case ParamType::Choice: {
            if (py::isinstance<py::bool_>(value) && p.choices.size() == 2) {
                v.number = value.cast<bool>() ? 1 : 0;
                break;
            }
            if (!py::isinstance<py::str>(value)) bad();
            const std::string name = value.cast<std::string>();
            bool found = false;
            for (std::size_t i = 0; i < p.choices.size(); ++i)
                if (p.choices[i] == name) v.number = double(i), found = true;
            if (!found) bad();
            break;
        }
        case ParamType::Bool:
            if (!py::isinstance<py::bool_>(value)) bad();
            v.number = value.cast<bool>() ? 1 : 0;
            break;
        case ParamType::Color:
        case ParamType::OptionalColor:
        case ParamType::Vector: {
            if (value.is_none() && p.type == ParamType::OptionalColor) {
                v.hasColor = false;
                break;
            }
            if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) ||
                py::len(value) != 3)
                bad();
            const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
            double c[3];
            for (int i = 0; i < 3; ++i) c[i] = number(s[py::size_t(i)]);
            v.vector = {c[0], c[1], c[2]};
            v.color = {float(c[0]), float(c[1]), float(c[2])};
            break;
        }
        default:
            v.number = number(value);
    }
    p.set(owner, v);
}

//! A function's keywords, each bound to a table (or a special handler).
class Keywords {
  public:
    template <class Owner>
    Keywords& table(std::span<const Param<Owner>> params, Owner& owner) {
        for (const Param<Owner>& p : params)
            m_binders.push_back({keywordName(p.key), [&p, &owner](const py::handle& value) {
                                     setKeyword(p, value, owner);
                                 }});
        return *this;
    }
    Keywords& custom(std::string key, std::function<void(const py::handle&)> set) {
        m_binders.push_back({std::move(key), std::move(set)});
        return *this;
    }
    //! Every keyword of `kwargs` through its binder; an unknown one is a ValueError listing the
    //! known ones. None leaves a parameter at its default.
    void read(const py::kwargs& kwargs) const;

  private:
    struct Binder {
        std::string key;
        std::function<void(const py::handle&)> set;
    };
    std::vector<Binder> m_binders;
};

//! A docstring section: one line per parameter, "key: help (unit); range, default D".
template <class Owner>
std::string keywordDocs(std::span<const Param<Owner>> params, const Owner& defaults) {
    std::string out;
    for (const Param<Owner>& p : params) {
        std::string line = "    " + keywordName(p.key) + ": " + std::string(p.help);
        if (!p.unit.empty()) line += " (" + std::string(p.unit) + ")";
        line += "; " + rangeText(p) + ", default " + valueText(p, p.get(defaults));
        out += pythonSpelling(line) + "\n";
    }
    return out;
}

}  // namespace flarekit::python
