// SPDX-License-Identifier: Apache-2.0
#include "Script.h"

#include <array>
#include <cmath>

#include "core/JsonText.h"
#include "core/ParamJson.h"
#include "flarekit/ImageIO.h"
#include "flarekit/PostFxParams.h"

namespace flarekit::studio {

namespace {

using nlohmann::json;

//! An action's kind, its fields (required first, `?` marks an optional one) and what it does.
struct ActionSpec {
    std::string_view kind;
    std::array<std::string_view, 8> fields;
    std::string_view help;
};

constexpr ActionSpec kActions[] = {
    {"open",
     {"path"},
     "opens an image (any format the CLI reads) or a sequence (shot.####.exr, shot.%04d.exr: "
     "its first frame on disk); the light goes to its light"},
    {"load", {"preset"}, "loads a shipped preset by name or a JSON file (no question asked)"},
    {"choose",
     {"preset"},
     "picks a preset in the browser, as a click does: with unsaved edits the studio asks first"},
    {"answer", {"choice"}, "answers the open question: \"discard\" (the edits) or \"cancel\""},
    {"light", {"at"}, "puts the light at [x, y] image pixels (outside the frame is allowed)"},
    {"scene",
     {"path", "?method"},
     "opens a Scene JSON and renders its still as `flarekit render` does (visibility `method`, "
     "default raycast); then `light` aims its sun through a pixel and `export` writes the still "
     "(linear to EXR, through the view's curve to 8/16-bit) and prints the sun's direction"},
    {"drive",
     {"?method", "?frames"},
     "plays the demo drive (480x270) with a visibility `method` (default raycast) over its "
     "first `frames` frames (default 240); the next action waits for every frame"},
    {"coverage",
     {"path"},
     "writes the drive's coverage per frame as CSV (frame, time_s, coverage_raw, "
     "coverage_smoothed, in_frame: `flarekit demo`'s columns)"},
    {"diagnostics",
     {"dir"},
     "writes the drive's shown frame's diagnostic views into `dir` (made when missing): the "
     "GPU method's working textures as method-NAME.png (texture-mask: the sun map and intensity "
     "map; burnout: the mask, the 14x14 grid, the chain), and the same moment through the "
     "emulated PSP GE as psp-STEP.png (as `flarekit psp burnout --dump` names them), "
     "psp-occluders.png and psp.txt (the sun's pixel, coverage byte and CLUT alpha)"},
    {"frame",
     {"frame"},
     "shows frame `frame` of the open sequence (a frame number on disk; the light moves to "
     "that frame's own light unless it was placed) or of the drive (from 1)"},
    {"drag",
     {"from", "to", "?frames"},
     "drags the light with the pointer from [x, y] to [x, y] (image pixels) over `frames` "
     "frames (default 8), drawing each"},
    {"mode",
     {"kind"},
     "edits and shows the sprite preset (\"sprite\", `flarekit apply`), the post-process "
     "preset (\"postfx\", `flarekit postfx`) or the lens (\"lens\", `flarekit lens render`)"},
    {"set",
     {"key", "value", "?element", "?section", "?ghost", "?surface", "?pair", "?design_nm"},
     "sets a parameter: of element `element` (sprite, docs/presets.md), of a post-process "
     "`section` (bloom, ...) or `ghost` (docs/postfx.md), of the lens's `section` (render, "
     "aperture, job; `surface` with its index; `coating` with key `design`, a value \"none\", "
     "\"mgf2\" or \"broadband\", `design_nm` and a `surface` or all glass-air ones; "
     "`ghost_pair` with `pair` [first, second], key gain or tint: docs/lens.md), or of the "
     "preset without them"},
    {"add_ghost", {}, "post-process: adds a copy of the last ghost"},
    {"remove_ghost", {"ghost"}, "post-process: removes a ghost"},
    {"view",
     {"key", "value"},
     "sets a view setting: exposure, tonemap, flux_mode, intensity, backend"},
    {"select", {"element"}, "selects an element for the parameter panel"},
    {"hide", {"element"}, "switches an element off (its `visible` becomes false)"},
    {"show", {"element"}, "switches an element on"},
    {"solo", {"?element"}, "shows one element alone; without `element`, all again"},
    {"add", {"type"}, "adds an element of a type (glow, ring, ...) after the selection"},
    {"duplicate", {"element"}, "duplicates an element"},
    {"remove", {"element"}, "removes an element"},
    {"move", {"element", "to"}, "moves an element to another place in the list"},
    {"undo", {}, "undoes the last edit"},
    {"redo", {}, "redoes it"},
    {"split", {"at"}, "before/after split: the before half's share of the view, 0 to 1"},
    {"save",
     {"path"},
     "saves the preset (or the lens) as the JSON the CLI reads, or as an engine's file by its "
     "extension"},
    {"export",
     {"path", "?depth"},
     "renders at full size: EXR linear (float), PNG (8-bit) and TIFF (16-bit) through the view's "
     "exposure and curve; `depth` (8, 16, half, float) overrides the extension's"},
    {"screenshot", {"path"}, "writes the whole window as an 8-bit PNG"},
    {"pick",
     {"at"},
     "lens: names the drawn ghost nearest [x, y] (image pixels), as a right click does, and "
     "prints it: \"picked ghost of surfaces 7 and 3 ...\""},
    {"panel",
     {"name"},
     "shows a tab of the bottom strip: \"components\" (the passes) or \"presets\" (the "
     "browser)"},
    {"wait", {"?frames"}, "draws `frames` frames (default 1) doing nothing"},
};

const ActionSpec* specOf(const std::string& kind) {
    for (const ActionSpec& s : kActions)
        if (s.kind == kind) return &s;
    return nullptr;
}

std::string knownKinds() {
    std::string list;
    for (const ActionSpec& s : kActions) {
        if (!list.empty()) list += ", ";
        list += s.kind;
    }
    return list;
}

Error failAt(const Action& a, const std::string& what) {
    return invalidInput(a.where + ": " + what);
}

Result<int> elementOf(const Document& doc, const Action& a, const char* field = "element") {
    const json& v = a.args[field];
    const int n = int(doc.preset().elements.size());
    if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() >= n)
        return failAt(a, std::string(field) + ": expected an element index in [0, " +
                             std::to_string(n - 1) + "], got " + jsonExcerpt(v));
    return int(v.get<long long>());
}

template <class Owner>
Result<ParamValue> valueOf(std::span<const Param<Owner>> table, const Action& a,
                           std::uint32_t applies, const std::string& owner) {
    const std::string key = a.args["key"].is_string() ? a.args["key"].get<std::string>() : "";
    const Param<Owner>* p = findParam(table, key);
    if (!p || !(p->appliesTo & applies)) {
        std::string known;
        for (const Param<Owner>& q : table)
            if (q.appliesTo & applies) {
                if (!known.empty()) known += ", ";
                known += q.key;
            }
        return failAt(a, std::string("key: ") + jsonExcerpt(a.args["key"]) +
                             " is not a parameter of " + owner + " (expected one of: " + known +
                             ")");
    }
    return readParamValue(*p, a.args["value"], JsonPlace(a.where, key));
}

}  // namespace

Result<std::vector<Action>> loadScript(const std::string& path) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    JsonLimits limits;
    limits.what = "a script";
    auto doc = parseJsonText(*text, path, limits);
    if (!doc) return doc.error();
    if (!doc->is_object() || !doc->contains("actions") || !(*doc)["actions"].is_array())
        return invalidInput(path + ": expected an object {\"actions\": [...]}");
    std::vector<Action> actions;
    const json& list = (*doc)["actions"];
    for (std::size_t i = 0; i < list.size(); ++i) {
        Action a{"", list[i], path + ": actions[" + std::to_string(i) + "]"};
        if (!a.args.is_object() || !a.args.contains("action") || !a.args["action"].is_string())
            return failAt(
                a, std::string("expected an object with \"action\": one of ") + knownKinds());
        a.kind = a.args["action"].get<std::string>();
        const ActionSpec* spec = specOf(a.kind);
        if (!spec)
            return failAt(a, std::string("action: unknown action ") +
                                 jsonExcerpt(a.args["action"]) +
                                 " (expected one of: " + knownKinds() + ")");
        for (const auto& [key, value] : a.args.items()) {
            bool known = key == "action";
            for (std::string_view f : spec->fields)
                known = known || (!f.empty() && (f == key || (f[0] == '?' && f.substr(1) == key)));
            if (!known) return failAt(a, key + ": not a field of \"" + a.kind + "\"");
        }
        for (std::string_view f : spec->fields)
            if (!f.empty() && f[0] != '?' && !a.args.contains(std::string(f)))
                return failAt(a, std::string(f) + ": missing (\"" + a.kind + "\" needs it)");
        actions.push_back(std::move(a));
    }
    return actions;
}

Result<Point> actionPoint(const Action& a, const char* field) {
    const json& v = a.args[field];
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
        return failAt(
            a, std::string(field) + ": expected [x, y] in image pixels, got " + jsonExcerpt(v));
    return Point{v[0].get<float>(), v[1].get<float>()};
}

Result<int> actionFrames(const Action& a, int fallback) {
    // A drag or wait of 100,000 frames is half an hour at 60 frames/s: past any real script.
    constexpr long long kMaxFrames = 100000;
    if (!a.args.contains("frames")) return fallback;
    const json& v = a.args["frames"];
    if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > kMaxFrames)
        return failAt(a, "frames: expected an integer in [1, " + std::to_string(kMaxFrames) +
                             "], got " + jsonExcerpt(v));
    return int(v.get<long long>());
}

bool isWindowAction(const std::string& kind) {
    return kind == "drag" || kind == "screenshot" || kind == "choose" || kind == "answer" ||
           kind == "drive" || kind == "coverage" || kind == "diagnostics" || kind == "scene" ||
           kind == "wait" || kind == "split" || kind == "panel" || kind == "pick";
}

Status runDocumentAction(Document& doc, const Action& a) {
    const auto withWhere = [&](Status s) -> Status {
        if (s) return s;
        return invalidInput(a.where + ": " + s.error().message);
    };
    const auto pathOf = [&]() -> Result<std::string> {
        const json& v = a.args.contains("path") ? a.args["path"] : a.args["preset"];
        if (!v.is_string() || v.get<std::string>().empty())
            return failAt(a, std::string("expected a file name, got ") + jsonExcerpt(v));
        return v.get<std::string>();
    };
    const std::string& k = a.kind;
    if (k == "open" || k == "load" || k == "save" || k == "export") {
        auto path = pathOf();
        if (!path) return path.error();
        if (k == "open") return withWhere(doc.openImage(*path));
        if (k == "load") return withWhere(doc.loadPreset(*path));
        if (k == "save") return withWhere(doc.savePreset(*path));
        SampleFormat depth = SampleFormat::Auto;
        if (a.args.contains("depth")) {
            const json& d = a.args["depth"];
            const std::string text = d.is_number_integer() ? std::to_string(d.get<int>())
                                     : d.is_string()       ? d.get<std::string>()
                                                           : "";
            bool found = false;
            for (std::size_t i = 1; i < std::size(kSampleFormatNames); ++i)
                if (kSampleFormatNames[i] == text) depth = SampleFormat(i), found = true;
            if (!found)
                return failAt(
                    a, "depth: expected 8, 16, \"half\" or \"float\", got " + jsonExcerpt(d));
        }
        return withWhere(doc.exportRender(*path, depth));
    }
    if (k == "light") {
        auto at = actionPoint(a, "at");
        if (!at) return at.error();
        doc.light = *at, doc.lightPlacedByHand = true;
        return Ok{};
    }
    if (k == "frame") {
        const json& v = a.args["frame"];
        if (!doc.isSequence()) return failAt(a, "no image sequence is open");
        if (!v.is_number_integer())
            return failAt(a, "frame: expected a frame number, got " + jsonExcerpt(v));
        return withWhere(
            doc.showFrame(int(std::clamp<long long>(v.get<long long>(), -1, 1LL << 30))));
    }
    if (k == "mode") {
        const json& v = a.args["kind"];
        for (std::size_t i = 0; i < std::size(kFlareKindNames); ++i)
            if (v.is_string() && v.get<std::string>() == kFlareKindNames[i]) {
                doc.kind = FlareKind(i);
                return Ok{};
            }
        return failAt(a,
                      "kind: expected \"sprite\", \"postfx\" or \"lens\", got " + jsonExcerpt(v));
    }
    if (k == "add_ghost") {
        if (doc.postFx().ghosts.size() >= std::size_t(kMaxGhosts))
            return failAt(
                a, "the preset has the most ghosts it may (" + std::to_string(kMaxGhosts) + ")");
        doc.addGhost();
        return Ok{};
    }
    if (k == "remove_ghost" || (k == "set" && a.args.contains("ghost"))) {
        const json& v = a.args["ghost"];
        const int n = int(doc.postFx().ghosts.size());
        if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() >= n)
            return failAt(a, "ghost: expected a ghost index in [0, " + std::to_string(n - 1) +
                                 "], got " + jsonExcerpt(v));
        const int g = int(v.get<long long>());
        if (k == "remove_ghost") {
            doc.removeGhost(g);
            return Ok{};
        }
        auto value = valueOf<GhostParams>(kGhostParams, a, ~0u, "a ghost");
        if (!value) return value.error();
        Status s = doc.setGhostParam(g, a.args["key"].get<std::string>(), *value);
        doc.commit();
        return withWhere(s);
    }
    if (k == "set" && doc.kind == FlareKind::Lens) {
        const std::string section =
            a.args["section"].is_string() ? a.args["section"].get<std::string>() : "";
        const auto apply = [&](auto table, auto& owner) -> Status {
            using Owner = std::decay_t<decltype(owner)>;
            auto value = valueOf<Owner>(table, a, ~0u, "the lens's " + section);
            if (!value) return value.error();
            findParam<Owner>(table, a.args["key"].get<std::string>())->set(owner, *value);
            doc.commit();
            return Ok{};
        };
        const std::string key = a.args["key"].is_string() ? a.args["key"].get<std::string>() : "";
        const int surfaces = int(doc.lens().surfaces.size());
        const auto surfaceOf = [&]() -> Result<int> {
            const json& v = a.args["surface"];
            if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() >= surfaces)
                return failAt(a, "surface: expected a surface index in [0, " +
                                     std::to_string(surfaces - 1) + "], got " + jsonExcerpt(v));
            return int(v.get<long long>());
        };
        if (section == "surface") {
            auto i = surfaceOf();
            if (!i) return i.error();
            auto value = valueOf<LensSurface>(
                std::span<const Param<LensSurface>>(kLensSurfaceParams), a, ~0u, "a lens surface");
            if (!value) return value.error();
            Status s = doc.setLensSurfaceParam(*i, key, *value);
            doc.commit();
            return withWhere(s);
        }
        if (section == "coating") {
            const json& v = a.args["value"];
            if (key != "design" || !v.is_string())
                return failAt(a,
                              "coating: expected key \"design\" and a value \"none\", \"mgf2\" "
                              "or \"broadband\", got " +
                                  jsonExcerpt(a.args["key"]) + " " + jsonExcerpt(v));
            const json& nm = a.args.contains("design_nm") ? a.args["design_nm"] : json(550);
            if (!nm.is_number())
                return failAt(a, "design_nm: expected a wavelength in nm, got " + jsonExcerpt(nm));
            int surface = -1;
            if (a.args.contains("surface")) {
                auto i = surfaceOf();
                if (!i) return i.error();
                surface = *i;
            }
            Status s = doc.setLensCoating(surface, v.get<std::string>(), nm.get<double>());
            doc.commit();
            return withWhere(s);
        }
        if (section == "ghost_pair") {
            const json& v = a.args["pair"];
            if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() ||
                !v[1].is_number_integer())
                return failAt(a,
                              "pair: expected [first, second], the surfaces the ghost reflects "
                              "at, got " +
                                  jsonExcerpt(v));
            auto value = valueOf<GhostPairLook>(
                std::span<const Param<GhostPairLook>>(kGhostPairParams), a, ~0u, "a ghost's look");
            if (!value) return value.error();
            Status s = doc.setGhostPairParam(int(v[0].get<long long>()), int(v[1].get<long long>()),
                                             key, *value);
            doc.commit();
            return withWhere(s);
        }
        if (section == "render")
            return apply(std::span<const Param<LensRenderOptions>>(kLensRenderParams),
                         doc.lensJob().render);
        if (section == "aperture")
            return apply(std::span<const Param<LensAperture>>(kLensApertureParams), doc.aperture());
        if (section == "job")
            return apply(std::span<const Param<LensJobOptions>>(kLensJobParams), doc.lensJob());
        return failAt(a,
                      "section: expected \"render\", \"aperture\", \"job\", \"surface\", "
                      "\"coating\" or \"ghost_pair\" for a lens, got " +
                          jsonExcerpt(a.args["section"]));
    }
    if (k == "set" && a.args.contains("section")) {
        const std::string section =
            a.args["section"].is_string() ? a.args["section"].get<std::string>() : "";
        Status s = failAt(a,
                          "section: expected one of bright, bloom, halo, streaks, chromatic, "
                          "starburst, dirt, tonemap, got " +
                              jsonExcerpt(a.args["section"]));
        forEachPostFxSection(doc.postFx(), [&](std::string_view name, auto table, auto& owner) {
            using Owner = std::decay_t<decltype(owner)>;
            if (name != section) return;
            auto value = valueOf<Owner>(table, a, ~0u, "the " + section + " section");
            if (!value) {
                s = value.error();
                return;
            }
            s = withWhere(doc.setPostFxParam(section, a.args["key"].get<std::string>(), *value));
        });
        doc.commit();
        return s;
    }
    if (k == "set" && doc.kind == FlareKind::PostFx && !a.args.contains("element")) {
        auto v = valueOf<PostFxParams>(kPostFxTopParams, a, ~0u, "the post-process preset");
        if (!v) return v.error();
        Status s = doc.setPostFxParam("", a.args["key"].get<std::string>(), *v);
        doc.commit();
        return withWhere(s);
    }
    if (k == "set") {
        if (!a.args.contains("element")) {
            auto v = valueOf<Preset>(kPresetParams, a, ~0u, "the preset");
            if (!v) return v.error();
            return withWhere(doc.setPresetParam(a.args["key"].get<std::string>(), *v));
        }
        auto i = elementOf(doc, a);
        if (!i) return i.error();
        const ElementType type = doc.preset().elements[std::size_t(*i)].type;
        auto v = valueOf<ElementParams>(kElementParams, a, typeBit(type),
                                        "a " + std::string(elementTypeName(type)) + " element");
        if (!v) return v.error();
        Status s = doc.setElementParam(*i, a.args["key"].get<std::string>(), *v);
        doc.commit();
        return withWhere(s);
    }
    if (k == "view") {
        auto v = valueOf<ViewSettings>(kViewParams, a, ~0u, "the view");
        if (!v) return v.error();
        findParam<ViewSettings>(kViewParams, a.args["key"].get<std::string>())->set(doc.view, *v);
        return Ok{};
    }
    if (k == "undo") return doc.undo(), Status(Ok{});
    if (k == "redo") return doc.redo(), Status(Ok{});
    if (k == "add") {
        const auto type = a.args["type"].is_string()
                              ? parseElementType(a.args["type"].get<std::string>())
                              : std::nullopt;
        if (!type || *type == ElementType::Image)
            return failAt(a,
                          "type: expected an element type other than image (an image element "
                          "needs its texture file), got " +
                              jsonExcerpt(a.args["type"]));
        doc.addElement(*type);
        return Ok{};
    }
    if (k == "solo" && !a.args.contains("element")) {
        doc.solo = -1;
        return Ok{};
    }
    auto i = elementOf(doc, a);
    if (!i) return i.error();
    if (k == "select") doc.selected = *i;
    if (k == "hide" || k == "show") doc.setVisible(*i, k == "show");
    if (k == "solo") doc.solo = *i;
    if (k == "duplicate") doc.duplicateElement(*i);
    if (k == "remove") doc.removeElement(*i);
    if (k == "move") {
        auto to = elementOf(doc, a, "to");
        if (!to) return to.error();
        doc.moveElement(*i, *to);
    }
    return Ok{};
}

std::string scriptReference() {
    std::string out = "| action | fields | what it does |\n|---|---|---|\n";
    for (const ActionSpec& s : kActions) {
        std::string fields;
        for (std::string_view f : s.fields) {
            if (f.empty()) continue;
            if (!fields.empty()) fields += ", ";
            const bool optional = f[0] == '?';
            fields += '`';
            fields += optional ? f.substr(1) : f;
            fields += optional ? "` (optional)" : "`";
        }
        out += "| `";
        out += s.kind;
        out += "` | ";
        out += fields;
        out += " | ";
        out += s.help;
        out += " |\n";
    }
    return out;
}

}  // namespace flarekit::studio
