// SPDX-License-Identifier: Apache-2.0
// The one CLI binder of parameter tables (flarekit/Param.h): a numeric flag gets its name,
// help, default and range check from the parameter's description, so a range typed in a
// table is the range the CLI enforces.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "flarekit/Param.h"
#include "flarekit/ParamText.h"

namespace flarekit::cli {

//! "expected an integer in [1, 4096], got 0" for a text that does not fit the parameter.
template <class Owner>
CLI::Validator paramValidator(const Param<Owner>& p) {
    return CLI::Validator(
        [p](std::string& text) -> std::string {
            double x = 0;
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, x);
            if (ec == std::errc() && ptr == end && numberFits(p, x)) return {};
            return "expected " + expectedText(p) + ", got " + text;
        },
        rangeText(p));
}

template <class Owner>
std::string paramHelp(const Param<Owner>& p) {
    return std::string(p.help) + (p.unit.empty() ? "" : " (" + std::string(p.unit) + ")");
}

//! A table key as a flag: "ghost_gain" is --ghost-gain (flags are spelt with hyphens).
inline std::string flagName(std::string_view key) {
    std::string flag = "--" + std::string(key);
    for (char& c : flag)
        if (c == '_') c = '-';
    return flag;
}

//! --<key> (hyphens for underscores) writing into `target` through the description (numeric
//! parameters). A key with underscores keeps its old spelling (--ghost_gain) as a hidden alias
//! that scripts may still use; the help names it as deprecated.
template <class Owner>
CLI::Option* addParamOption(CLI::App* cmd, const Param<Owner>& p, Owner& target) {
    const auto set = [p, &target](double x) {
        ParamValue v;
        v.number = x;
        p.set(target, v);
    };
    const std::string flag = flagName(p.key), old = "--" + std::string(p.key);
    auto* option = cmd->add_option_function<double>(
        flag, set,
        paramHelp(p) + (flag == old ? "" : " (" + old + " still works; deprecated spelling)"));
    option->check(paramValidator(p));
    option->type_name(p.type == ParamType::Number ? "FLOAT" : "INT");
    option->default_str(valueText(p, p.get(target)));
    if (flag != old) {
        auto* alias = cmd->add_option_function<double>(old, set, "");
        alias->check(paramValidator(p));
        alias->group("");  // hidden from --help
    }
    return option;
}

//! The parameter `key` of `table` as --key (a key missing from the table is a programming error).
template <class Owner>
CLI::Option* addParamOption(CLI::App* cmd, std::span<const Param<Owner>> table,
                            std::string_view key, Owner& target) {
    const Param<Owner>* p = findParam(table, key);
    if (!p) throw std::logic_error("no parameter '" + std::string(key) + "'");
    return addParamOption(cmd, *p, target);
}

//! A choice parameter as --key NAME, the names and the default from its description.
template <class Owner>
CLI::Option* addParamChoice(CLI::App* cmd, std::span<const Param<Owner>> table,
                            std::string_view key, Owner& target) {
    const Param<Owner>* p = findParam(table, key);
    if (!p || p->type != ParamType::Choice)
        throw std::logic_error("no choice parameter '" + std::string(key) + "'");
    std::vector<std::string> names(p->choices.begin(), p->choices.end());
    const Param<Owner> described = *p;
    auto* option = cmd->add_option_function<std::string>(
        flagName(p->key),
        [described, names, &target](const std::string& name) {
            ParamValue v;
            v.number = double(std::find(names.begin(), names.end(), name) - names.begin());
            described.set(target, v);
        },
        paramHelp(*p));
    option->check(CLI::IsMember(names));
    option->default_str(names[std::size_t(p->get(target).number)]);
    return option;
}

//! Every numeric parameter of a table as a flag.
template <class Owner>
void addParamOptions(CLI::App* cmd, std::span<const Param<Owner>> table, Owner& target) {
    for (const Param<Owner>& p : table) {
        if (p.isNumeric()) addParamOption(cmd, p, target);
    }
}

//! Every text parameter of a table as --key TEXT.
template <class Owner>
void addTextOptions(CLI::App* cmd, std::span<const TextParam<Owner>> table, Owner& target) {
    for (const TextParam<Owner>& p : table)
        cmd->add_option(flagName(p.key), target.*(p.member), std::string(p.help));
}

//! An override flag: `flag` (e.g. "--threshold") checked against `p`, stored in `out` only when
//! given; the help says the default comes from elsewhere (a preset).
template <class Owner, class T>
CLI::Option* addParamOverride(CLI::App* cmd, const std::string& flag, const Param<Owner>& p,
                              std::optional<T>& out, const std::string& defaultFrom) {
    auto* option = cmd->add_option_function<double>(
        flag, [&out](double x) { out = T(x); }, paramHelp(p) + " (default: " + defaultFrom + ")");
    option->check(paramValidator(p));
    option->type_name(p.type == ParamType::Number ? "FLOAT" : "INT");
    return option;
}

}  // namespace flarekit::cli
