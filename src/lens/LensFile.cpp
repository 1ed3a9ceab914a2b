// SPDX-License-Identifier: Apache-2.0
// Reading presets/lenses/NAME.json: the format's ranges through the parameter tables, then the
// physical checks a prescription must pass before anything is traced through it.
#include <cmath>
#include <sstream>

#include "core/ParamJson.h"
#include "core/PresetFiles.h"
#include "flarekit/Lens.h"
#include "flarekit/ParamText.h"
#include "lens/LensTrace.h"

namespace flarekit {

namespace {

constexpr std::string_view kLensDir = "lenses";

//! A design's wavelength: within the visible, where a lens's coatings are centred.
constexpr double kMinDesignNm = 380.0, kMaxDesignNm = 780.0;
//! Layers in one stack: real lens coatings have 1-12; more is a filter, not a lens coating.
constexpr std::size_t kMaxCoatingLayers = 16;

constexpr const char* kCoatingForms =
    "\"none\", \"mgf2\", \"broadband\", {\"design\": NAME, \"design_nm\": "
    "380-780}, {\"n\": 1-3, \"thickness_nm\": 0-10000} or {\"layers\": [{\"n\", "
    "\"thickness_nm\"}, ...]}";

//! {"n": 1.38, "thickness_nm": 99.6}: one layer.
Result<CoatingLayer> readLayer(const nlohmann::json& v, const JsonPlace& place) {
    if (!v.is_object())
        return place.fail("expected {\"n\": ..., \"thickness_nm\": ...}, got " + jsonExcerpt(v));
    CoatingLayer c;
    for (const auto& [key, value] : v.items()) {
        if ((key != "n" && key != "thickness_nm") || !value.is_number())
            return (place / key)
                .fail("expected \"n\" (1-3) or \"thickness_nm\" (0-10000), got " +
                      jsonExcerpt(value));
        (key == "n" ? c.n : c.thicknessNm) = value.get<double>();
    }
    if (!(c.n >= 1.0 && c.n <= 3.0))
        return (place / "n").fail("expected a number in [1, 3], got " + formatParamNumber(c.n));
    if (!(c.thicknessNm > 0.0 && c.thicknessNm <= 10000.0))
        return (place / "thickness_nm")
            .fail("expected a number in (0, 10000], got " + formatParamNumber(c.thicknessNm));
    return c;
}

//! The index of a coating design's name; -1 for none.
int designIndex(std::string_view name) {
    for (std::size_t i = 0; i < std::size(kCoatingDesignNames); ++i)
        if (kCoatingDesignNames[i] == name) return int(i);
    return -1;
}

//! {"design": "broadband", "design_nm": 520}: a named design at its wavelength.
Result<LensCoating> readDesign(const nlohmann::json& v, const JsonPlace& place) {
    double designNm = kMgF2DesignNm;
    int design = -1;
    for (const auto& [key, value] : v.items()) {
        if (key == "design" && value.is_string())
            design = designIndex(value.get<std::string>());
        else if (key == "design_nm" && value.is_number())
            designNm = value.get<double>();
        else
            return (place / key)
                .fail("expected \"design\" (a name) or \"design_nm\", got " + jsonExcerpt(value));
    }
    if (design < 0) return (place / "design").fail("expected \"mgf2\" or \"broadband\"");
    if (!(designNm >= kMinDesignNm && designNm <= kMaxDesignNm))
        return (place / "design_nm")
            .fail("expected a wavelength in [380, 780] nm, got " + formatParamNumber(designNm));
    return coatingDesign(CoatingDesign(design), designNm);
}

//! Any of kCoatingForms.
Result<LensCoating> readCoating(const nlohmann::json& v, const JsonPlace& place) {
    if (v.is_string()) {
        if (v.get<std::string>() == "none") return LensCoating{};
        const int design = designIndex(v.get<std::string>());
        if (design >= 0) return coatingDesign(CoatingDesign(design), kMgF2DesignNm);
    }
    if (v.is_object() && v.contains("design")) return readDesign(v, place);
    if (v.is_object() && v.contains("layers")) {
        const nlohmann::json& layers = v["layers"];
        if (v.size() != 1 || !layers.is_array() || layers.empty() ||
            layers.size() > kMaxCoatingLayers)
            return (place / "layers").fail("expected 1 to 16 layers, got " + jsonExcerpt(layers));
        LensCoating c;
        for (std::size_t i = 0; i < layers.size(); ++i) {
            auto layer = readLayer(layers[i], (place / "layers").index(i));
            if (!layer) return layer.error();
            c.layers.push_back(*layer);
        }
        return c;
    }
    if (v.is_object()) {
        auto layer = readLayer(v, place);
        if (!layer) return layer.error();
        return LensCoating{{*layer}};
    }
    return place.fail(std::string("expected ") + kCoatingForms + ", got " + jsonExcerpt(v));
}

Status checkPhysics(const Lens& lens, const JsonPlace& place) {
    const JsonPlace surfaces = place / "surfaces";
    if (lens.surfaces.size() < 2) return surfaces.fail("expected at least 2 surfaces");
    int stops = 0;
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
        const LensSurface& s = lens.surfaces[i];
        const JsonPlace at = surfaces.index(i);
        if (s.stop) {
            ++stops;
            if (s.radius != 0.0)
                return (at / "radius").fail("the stop is flat: expected no radius");
        }
        if (s.radius != 0.0 && s.semiAperture >= std::fabs(s.radius))
            return (at / "semi_aperture")
                .fail(formatParamNumber(s.semiAperture) + " is not below |radius| " +
                      formatParamNumber(std::fabs(s.radius)) + ": the sphere has no such zone");
        if (i + 1 < lens.surfaces.size()) {
            const LensSurface& next = lens.surfaces[i + 1];
            const double h = std::min(s.semiAperture, next.semiAperture);
            // The axial gap at the rim of the smaller clear aperture: surfaces that cross
            // there would be glass (or air) of negative thickness.
            const double edge =
                s.thickness + lens::surfaceSag(next.radius, h) - lens::surfaceSag(s.radius, h);
            if (edge < 0.0)
                return (at / "thickness")
                    .fail(formatParamNumber(s.thickness) + " makes surfaces " + std::to_string(i) +
                          " and " + std::to_string(i + 1) + " cross within their clear apertures " +
                          "(gap " + formatParamNumber(edge) + " mm at height " +
                          formatParamNumber(h) + " mm)");
        } else if (s.thickness <= 0.0) {
            return (at / "thickness")
                .fail("expected the sensor behind the last surface (a positive number), got " +
                      formatParamNumber(s.thickness));
        }
    }
    if (stops != 1)
        return surfaces.fail("expected exactly one surface with \"stop\": true, found " +
                             std::to_string(stops));
    const int n = int(lens.surfaces.size());
    for (std::size_t i = 0; i < lens.ghostPairs.size(); ++i) {
        const GhostPairLook& g = lens.ghostPairs[i];
        const JsonPlace at = (place / "ghost_pairs").index(i) / "surfaces";
        if (!(g.second >= 0 && g.second < g.first && g.first < n))
            return at.fail("expected [first, second] with " + std::to_string(n) +
                           " > first > second >= 0 (the light reflects at first, then at "
                           "second), got [" +
                           std::to_string(g.first) + ", " + std::to_string(g.second) + "]");
        if (lens.surfaces[std::size_t(g.first)].stop || lens.surfaces[std::size_t(g.second)].stop)
            return at.fail("surface " + std::to_string(lens.stopIndex()) +
                           " is the stop, which never reflects");
        for (std::size_t k = 0; k < i; ++k)
            if (lens.ghostPairs[k].first == g.first && lens.ghostPairs[k].second == g.second)
                return at.fail("the pair [" + std::to_string(g.first) + ", " +
                               std::to_string(g.second) + "] is already given at ghost_pairs[" +
                               std::to_string(k) + "]");
    }
    return Ok{};
}

//! {"surfaces": [first, second], "gain": ..., "tint": [r, g, b]}.
Result<GhostPairLook> readGhostPair(const nlohmann::json& v, const JsonPlace& place) {
    if (!v.is_object() || !v.contains("surfaces"))
        return place.fail(
            "expected {\"surfaces\": [first, second], \"gain\": ..., \"tint\": [r, g, b]}, "
            "got " +
            jsonExcerpt(v));
    const nlohmann::json& sv = v["surfaces"];
    const auto index = [](const nlohmann::json& x) {
        return x.is_number_integer() && x.get<long long>() >= 0 && x.get<long long>() < 4096;
    };
    if (!sv.is_array() || sv.size() != 2 || !index(sv[0]) || !index(sv[1]))
        return (place / "surfaces")
            .fail("expected [first, second], the surfaces' indices, got " + jsonExcerpt(sv));
    GhostPairLook g;
    g.first = int(sv[0].get<long long>()), g.second = int(sv[1].get<long long>());
    if (auto e = readParams(v, std::span<const Param<GhostPairLook>>(kGhostPairParams), g, place,
                            {"surfaces"}))
        return *e;
    return g;
}

bool sameCoating(const LensCoating& a, const LensCoating& b) {
    if (a.layers.size() != b.layers.size()) return false;
    for (std::size_t i = 0; i < a.layers.size(); ++i)
        if (a.layers[i].n != b.layers[i].n || a.layers[i].thicknessNm != b.layers[i].thicknessNm)
            return false;
    return true;
}

nlohmann::json coatingJson(const LensCoating& c) {
    if (c.layers.empty()) return "none";
    nlohmann::json layers = nlohmann::json::array();
    for (const CoatingLayer& l : c.layers)
        layers.push_back({{"n", l.n}, {"thickness_nm", l.thicknessNm}});
    return {{"layers", layers}};
}

}  // namespace

bool takesLensCoating(const Lens& lens, std::size_t i) {
    const LensSurface& s = lens.surfaces[i];
    const bool airBefore = i == 0 || lens.surfaces[i - 1].nd == 1.0;
    return !s.stop && airBefore != (s.nd == 1.0);
}

int Lens::stopIndex() const {
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        if (surfaces[i].stop) return int(i);
    }
    return -1;
}

std::vector<std::string> lensNames() {
    return presetNamesIn(std::string(kLensDir));
}

Result<Lens> parseLens(const std::string& text, const std::string& source) {
    JsonLimits limits;
    limits.what = "a lens";
    auto doc = parseJsonText(text, source, limits);
    if (!doc) return doc.error();
    const nlohmann::json& j = *doc;
    const JsonPlace place(source);
    if (!j.is_object()) return place.fail("expected an object, got " + jsonExcerpt(j));
    Lens lens;
    std::vector<bool> ownCoating;  //!< per surface: whether it states its own coating
    for (const auto& [key, value] : j.items()) {
        const JsonPlace at = place / key;
        if (key == "coating") {
            auto c = readCoating(value, at);
            if (!c) return c.error();
            lens.coating = *c;
        } else if (key == "name" || key == "source") {
            if (!value.is_string()) return at.fail("expected a string, got " + jsonExcerpt(value));
            (key == "name" ? lens.name : lens.source) = value.get<std::string>();
        } else if (key == "f_number" || key == "patent_focal_length_mm") {
            if (!value.is_number() || !(value.get<double>() > 0.0) || !(value.get<double>() < 1e5))
                return at.fail("expected a positive number, got " + jsonExcerpt(value));
            (key == "f_number" ? lens.fNumber : lens.patentFocalLength) = value.get<double>();
        } else if (key == "surfaces") {
            if (!value.is_array()) return at.fail("expected an array, got " + jsonExcerpt(value));
            if (value.size() > 512) return at.fail("expected at most 512 surfaces");
            for (std::size_t i = 0; i < value.size(); ++i) {
                LensSurface s;
                const JsonPlace si = at.index(i);
                if (auto e = readParams(value[i],
                                        std::span<const Param<LensSurface>>(kLensSurfaceParams), s,
                                        si, {"coating"}))
                    return *e;
                if (value[i].contains("coating")) {
                    auto c = readCoating(value[i]["coating"], si / "coating");
                    if (!c) return c.error();
                    s.coating = *c;
                }
                ownCoating.push_back(value[i].contains("coating"));
                if (!value[i].contains("n_d") && value[i].contains("v_d"))
                    return (si / "v_d").fail("given without n_d: air does not disperse");
                lens.surfaces.push_back(s);
            }
        } else if (key == "aperture") {
            if (auto e =
                    readParams(value, std::span<const Param<LensAperture>>(kLensApertureParams),
                               lens.aperture, at))
                return *e;
        } else if (key == "ghost_pairs") {
            if (!value.is_array() || value.size() > 4096)
                return at.fail("expected an array of at most 4096 pairs, got " +
                               jsonExcerpt(value));
            for (std::size_t i = 0; i < value.size(); ++i) {
                auto g = readGhostPair(value[i], at.index(i));
                if (!g) return g.error();
                lens.ghostPairs.push_back(*g);
            }
        } else if (key == "sensor") {
            if (auto e = readParams(value, std::span<const Param<LensSensor>>(kLensSensorParams),
                                    lens.sensor, at))
                return *e;
        } else {
            return at.fail(
                "unknown key (expected one of: name, source, f_number, patent_focal_length_mm, "
                "coating, surfaces, aperture, sensor, ghost_pairs)");
        }
    }
    // The lens's coating goes on every glass-air surface that states none of its own; cemented
    // (glass-glass) surfaces and the stop stay bare.
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i)
        if (!ownCoating[i] && takesLensCoating(lens, i)) lens.surfaces[i].coating = lens.coating;
    if (!j.contains("surfaces")) return (place / "surfaces").fail("missing; expected an array");
    if (auto s = checkPhysics(lens, place); !s) return s.error();
    if (lens.name.empty()) lens.name = source;
    return lens;
}

Status validateLens(const Lens& lens, const std::string& what) {
    // Through the file itself: a lens in memory passes exactly when its file would.
    auto read = parseLens(lensToJson(lens), what);
    if (!read) return read.error();
    return Ok{};
}

std::string lensToJson(const Lens& lens) {
    using nlohmann::json;
    std::string out = "{\n";
    const auto line = [&out](const std::string& key, const json& v, bool last = false) {
        out += ' ';
        out += json(key).dump();
        out += ": ";
        out += v.dump();
        out += last ? "\n" : ",\n";
    };
    line("name", lens.name);
    if (!lens.source.empty()) line("source", lens.source);
    if (lens.fNumber > 0) line("f_number", lens.fNumber);
    if (lens.patentFocalLength > 0) line("patent_focal_length_mm", lens.patentFocalLength);
    line("coating", coatingJson(lens.coating));
    out += " \"surfaces\": [\n";
    for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
        const LensSurface& s = lens.surfaces[i];
        json j =
            writeParams(s, std::span<const Param<LensSurface>>(kLensSurfaceParams), LensSurface{});
        if (s.vd != 0.0) j["n_d"] = s.nd;  // v_d is read only beside n_d
        const LensCoating expected = takesLensCoating(lens, i) ? lens.coating : LensCoating{};
        if (!sameCoating(s.coating, expected)) j["coating"] = coatingJson(s.coating);
        out += "  ";
        out += j.dump();
        out += i + 1 < lens.surfaces.size() ? ",\n" : "\n";
    }
    out += " ],\n";
    line("aperture",
         writeParams(lens.aperture, std::span<const Param<LensAperture>>(kLensApertureParams),
                     LensAperture{}));
    const bool pairs = !lens.ghostPairs.empty();
    line("sensor",
         writeParams(lens.sensor, std::span<const Param<LensSensor>>(kLensSensorParams),
                     LensSensor{}),
         !pairs);
    if (pairs) {
        out += " \"ghost_pairs\": [\n";
        for (std::size_t i = 0; i < lens.ghostPairs.size(); ++i) {
            const GhostPairLook& g = lens.ghostPairs[i];
            json j = {{"surfaces", {g.first, g.second}}};
            j.update(writeParams(g, std::span<const Param<GhostPairLook>>(kGhostPairParams),
                                 GhostPairLook{}));
            out += "  ";
            out += j.dump();
            out += i + 1 < lens.ghostPairs.size() ? ",\n" : "\n";
        }
        out += " ]\n";
    }
    out += "}\n";
    return out;
}

std::array<double, 3> Lens::ghostPairFactor(int first, int second) const {
    for (const GhostPairLook& g : ghostPairs)
        if (g.first == first && g.second == second)
            return {g.gain * g.tint[0], g.gain * g.tint[1], g.gain * g.tint[2]};
    return {1.0, 1.0, 1.0};
}

Result<Lens> loadLens(const std::string& nameOrPath) {
    return loadPresetFile(nameOrPath, std::string(kLensDir), parseLens);
}

Result<Lens> stopDown(const Lens& lens, double fNumber) {
    const Paraxial p = paraxial(lens);
    if (!(fNumber > 0.0) || !std::isfinite(fNumber))
        return invalidInput("--f-number: expected a positive number");
    if (fNumber < p.fNumber * (1.0 - 1e-9)) {
        std::ostringstream os;
        os << lens.name << ": --f-number " << fNumber << " is wider than the stop as written (F/"
           << p.fNumber << "): a lens can only be stopped down";
        return invalidInput(os.str());
    }
    Lens out = lens;
    // Paraxially the entrance pupil scales with the stop, so the f-number goes as 1 / radius.
    out.surfaces[std::size_t(out.stopIndex())].semiAperture *= p.fNumber / fNumber;
    return out;
}

}  // namespace flarekit
