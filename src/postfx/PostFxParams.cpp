// SPDX-License-Identifier: Apache-2.0
// Post-process presets: JSON read through the parameter tables of flarekit/PostFxParams.h, one
// validator for JSON and code-built params, and the docs/postfx.md reference table.
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/ParamJson.h"
#include "core/PresetFiles.h"
#include "flarekit/ParamText.h"
#include "flarekit/PostFxParams.h"

namespace flarekit {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

Status checkGhost(const GhostParams& g, const std::string& at) {
    if (Status s = validateParams<GhostParams>(g, kGhostParams, at + "."); !s) return s;
    if (std::abs(g.scale) < kMinGhostScale) {
        return invalidInput(
            at +
            ".scale: expected |scale| >= 0.05 (a ghost that small magnifies one bloom texel "
            "over the frame), got " +
            std::to_string(g.scale));
    }
    return Ok{};
}

std::optional<Error> readSeries(const json& v, const JsonPlace& at, PostFxParams& p) {
    GhostParams base;
    GhostSeriesParams series;
    if (auto e = readParams<GhostParams>(v, kGhostParams, base, at,
                                         {"count", "spacing", "start", "tints"}))
        return e;
    for (const Param<GhostSeriesParams>& q : kGhostSeriesParams) {
        const auto it = v.find(std::string(q.key));
        if (it == v.end()) {
            if (q.key == "count") return (at / q.key).fail("missing; expected " + expectedText(q));
            continue;
        }
        auto value = readParamValue(q, *it, at / q.key);
        if (!value) return value.error();
        q.set(series, *value);
    }
    std::vector<Rgb> tints;
    if (auto it = v.find("tints"); it != v.end()) {
        if (!it->is_array() || it->empty() || it->size() > std::size_t(kMaxGhosts)) {
            return (at / "tints")
                .fail("expected an array of 1 to " + std::to_string(kMaxGhosts) + " colours, got " +
                      jsonExcerpt(*it));
        }
        const Param<GhostParams>& tint = *findParam<GhostParams>(kGhostParams, "tint");
        for (std::size_t i = 0; i < it->size(); ++i) {
            auto c = readParamValue(tint, (*it)[i], (at / "tints").index(i));
            if (!c) return c.error();
            tints.push_back(c->color);
        }
    }
    for (int i = 0; i < series.count; ++i) {
        GhostParams g = base;
        g.scale = float(double(series.start) - double(i) * double(series.spacing));
        if (!tints.empty()) g.tint = tints[std::size_t(i) % tints.size()];
        if (Status s = checkGhost(g, at.at() + " ghost " + std::to_string(i)); !s) {
            return invalidInput(at.source() + ": " + s.error().message);
        }
        p.ghosts.push_back(g);
    }
    return std::nullopt;
}

}  // namespace

Status validatePostFxParams(const PostFxParams& params) {
    if (params.ghosts.size() > std::size_t(kMaxGhosts)) {
        return invalidInput("ghosts: expected at most " + std::to_string(kMaxGhosts) +
                            " ghosts with ghost_series included, got " +
                            std::to_string(params.ghosts.size()));
    }
    for (std::size_t i = 0; i < params.ghosts.size(); ++i) {
        if (Status s = checkGhost(params.ghosts[i], "ghosts[" + std::to_string(i) + "]"); !s)
            return s;
    }
    if (Status s = validateParams<PostFxParams>(params, kPostFxTopParams, ""); !s) return s;
    Status status = Ok{};
    forEachPostFxSection(params, [&](std::string_view section, auto table, auto& owner) {
        if (status) status = validateParams(owner, table, std::string(section) + ".");
    });
    return status;
}

Result<PostFxParams> parsePostFxPreset(const std::string& jsonText, const std::string& source) {
    auto parsed = parseJsonText(jsonText, source);
    if (!parsed) return parsed.error();
    const json& doc = *parsed;
    const JsonPlace top(source);
    if (!doc.is_object()) return top.fail("expected an object, got " + jsonExcerpt(doc));
    PostFxParams p;
    p.name = fs::path(source).stem().string();
    for (const auto& item : doc.items()) {
        // Named references, not a structured binding: clang 14 (the fuzz build) cannot capture
        // a binding in the lambda below.
        const std::string& key = item.key();
        const json& value = item.value();
        bool section = false;
        std::optional<Error> error;
        forEachPostFxSection(p, [&](std::string_view name, auto table, auto& owner) {
            if (name != key) return;
            section = true;
            error = readParams(value, table, owner, top / key);
        });
        if (error) return *error;
        if (section) continue;
        if (key == "name" || key == "description") {
            if (!value.is_string())
                return (top / key).fail("expected a string, got " + jsonExcerpt(value));
            (key == "name" ? p.name : p.description) = value.get<std::string>();
        } else if (key == "source") {
            if (!value.is_object())
                return (top / key).fail("expected an object, got " + jsonExcerpt(value));
            p.source = value.dump();
        } else if (const Param<PostFxParams>* f = findParam<PostFxParams>(kPostFxTopParams, key)) {
            auto v = readParamValue(*f, value, top / key);
            if (!v) return v.error();
            f->set(p, *v);
        } else if (key == "ghosts") {
            if (!value.is_array() || value.size() > std::size_t(kMaxGhosts)) {
                return (top / key).fail("expected an array of at most " +
                                        std::to_string(kMaxGhosts) + " ghosts, got " +
                                        jsonExcerpt(value));
            }
            for (std::size_t i = 0; i < value.size(); ++i) {
                const JsonPlace at = (top / key).index(i);
                GhostParams g;
                if (auto e = readParams<GhostParams>(value[i], kGhostParams, g, at)) return *e;
                p.ghosts.push_back(g);  // |scale| is checked with the rest, below
            }
        } else if (key == "ghost_series") {
            if (auto e = readSeries(value, top / key, p)) return *e;
        } else {
            return (top / key).fail(
                "unknown key (expected one of: name, description, flare_intensity, bright, bloom, "
                "ghosts, ghost_series, halo, streaks, chromatic, starburst, dirt, tonemap, "
                "source)");
        }
    }
    if (Status s = validatePostFxParams(p); !s)
        return invalidInput(source + ": " + s.error().message);
    return p;
}

std::string postFxPresetToJson(const PostFxParams& params) {
    // Keys in the order the reader documents them; sections without a changed key left out.
    const PostFxParams defaults;
    std::string text = "{\n  \"name\": " + json(params.name).dump() + ",\n";
    if (!params.description.empty())
        text += "  \"description\": " + json(params.description).dump() + ",\n";
    const json top = writeParams<PostFxParams>(params, kPostFxTopParams, defaults);
    for (const auto& [key, value] : top.items())
        text += "  \"" + key + "\": " + value.dump() + ",\n";
    forEachPostFxSection(params, [&](std::string_view section, auto table, const auto& owner) {
        using Owner = std::decay_t<decltype(owner)>;
        const json keys = writeParams<Owner>(owner, table, Owner{});
        if (!keys.empty()) text += "  \"" + std::string(section) + "\": " + keys.dump() + ",\n";
    });
    if (json src = json::parse(params.source, nullptr, false); src.is_object())
        text += "  \"source\": " + src.dump() + ",\n";
    text += "  \"ghosts\": [";
    for (std::size_t i = 0; i < params.ghosts.size(); ++i)
        text += std::string(i ? ",\n    " : "\n    ") +
                writeParams<GhostParams>(params.ghosts[i], kGhostParams, GhostParams{}).dump();
    text += params.ghosts.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return text;
}

std::vector<std::string> shippedPostFxPresetNames() {
    return presetNamesIn("postfx");
}

Result<PostFxParams> loadPostFxPreset(const std::string& nameOrPath) {
    return loadPresetFile(nameOrPath, "postfx", parsePostFxPreset);
}

std::string postFxParameterReference() {
    PostFxParams defaults;
    const GhostParams ghost;
    const GhostSeriesParams series;
    auto lead = [](std::string_view s) {
        return [s](const auto&) { return std::string(s) + " | "; };
    };
    auto none = [](const auto&) { return std::string(); };
    std::string out =
        "| section | key | default | range | unit | meaning |\n|---|---|---|---|---|---|\n";
    out += markdownRows<PostFxParams>(kPostFxTopParams, &defaults, lead("(top)"), none);
    forEachPostFxSection(defaults, [&](std::string_view section, auto table, auto& owner) {
        out += markdownRows(table, &owner, lead(section), none);
        if (section == "bloom")
            out += markdownRows<GhostParams>(kGhostParams, &ghost, lead("ghosts[i], ghost_series"),
                                             none);
    });
    out += markdownRows<GhostSeriesParams>(kGhostSeriesParams, &series, lead("ghost_series"), none);
    out +=
        "| ghost_series | `tints` | | 1-32 colours | linear RGB | per-ghost tints, cycled; "
        "overrides `tint` |\n";
    return out;
}

}  // namespace flarekit
