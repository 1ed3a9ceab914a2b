// SPDX-License-Identifier: Apache-2.0
// Presets, post-process presets and lenses (list, load, validate), the lens ghost report, the
// element contact sheet and scene visibility.
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>

#include "Bindings.h"
#include "Convert.h"
#include "Keywords.h"
#include "core/PresetFiles.h"
#include "flarekit/Convert.h"
#include "flarekit/Flare.h"
#include "flarekit/Lens.h"
#include "flarekit/PostFxParams.h"
#include "flarekit/Visibility.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/GpuVisibility.h"
#endif

namespace flarekit::python {

namespace {

//! The kinds of preset file: where the shipped ones are and how each is checked.
struct Kind {
    const char* name;    //!< the keyword's value
    const char* subdir;  //!< under the presets' root
    Status (*validate)(const std::string& text, const std::string& source);
};
const Kind kKinds[] = {
    {"sprite", "",
     [](const std::string& t, const std::string& s) -> Status {
         auto p = parsePreset(t, s);
         return p ? Status(Ok{}) : Status(p.error());
     }},
    {"postfx", "postfx",
     [](const std::string& t, const std::string& s) -> Status {
         auto p = parsePostFxPreset(t, s);
         return p ? Status(Ok{}) : Status(p.error());
     }},
    {"lens", "lenses",
     [](const std::string& t, const std::string& s) -> Status {
         auto p = parseLens(t, s);
         return p ? Status(Ok{}) : Status(p.error());
     }},
};

const Kind& kindNamed(const std::string& name) {
    for (const Kind& k : kKinds)
        if (name == k.name) return k;
    throw py::value_error("kind: expected sprite, postfx or lens, got '" + name + "'");
}

py::object jsonLoads(const std::string& text) {
    return py::module_::import("json").attr("loads")(text);
}

py::dict visibilityDict(const VisibilityResult& r, int latency) {
    py::dict d;
    d["method"] = r.method;
    d["coverage"] = r.coverage;
    d["in_frame"] = r.inFrame;
    d["samples"] = r.samples;
    d["latency_frames"] = latency;
    d["cpu_ms"] = r.milliseconds;
    py::list lights;
    for (const LightVisibility& l : r.lights) {
        py::dict light;
        light["coverage"] = l.coverage;
        light["in_frame"] = l.inFrame;
        lights.append(light);
    }
    d["lights"] = lights;
    return d;
}

}  // namespace

void addData(py::module_& m) {
    m.def(
        "convert",
        [](const std::string& input, const std::string& output,
           const std::optional<std::string>& from, const std::optional<std::string>& to,
           float aspect, int referenceHeight, const std::string& unityBlendOrder,
           const std::string& unityAssets) {
            ConvertOptions options;
            const auto format = [](const std::optional<std::string>& name, const char* key) {
                std::optional<FlareFormat> f;
                if (!name) return f;
                f = parseFlareFormat(*name);
                if (!f)
                    throw py::value_error(std::string(key) +
                                          ": expected one of flarekit, playcanvas, babylon, "
                                          "three, unity, unreal, godot, got '" +
                                          *name + "'");
                return f;
            };
            options.from = format(from, "from_");
            options.to = format(to, "to");
            options.aspect = aspect;
            options.referenceHeight = referenceHeight;
            const auto order = std::find(std::begin(kUnityBlendOrderNames),
                                         std::end(kUnityBlendOrderNames), unityBlendOrder);
            if (order == std::end(kUnityBlendOrderNames))
                throw py::value_error("unity_blend_order: expected auto, current or early, got '" +
                                      unityBlendOrder + "'");
            options.unityBlendOrder = UnityBlendOrder(order - std::begin(kUnityBlendOrderNames));
            options.unityAssets = unityAssets;
            Result<std::vector<std::string>> warnings = internalError("not run");
            {
                py::gil_scoped_release release;
                warnings = convertFlare(input, output, options);
            }
            return unwrap(std::move(warnings));
        },
        py::arg("input"), py::arg("output"), py::arg("from_") = py::none(),
        py::arg("to") = py::none(), py::arg("aspect") = ConvertOptions{}.aspect,
        py::arg("reference_height") = ConvertOptions{}.referenceHeight,
        py::arg("unity_blend_order") = "auto", py::arg("unity_assets") = "",
        "convert(input, output, from_=None, to=None, aspect=1.7778, reference_height=1080, "
        "unity_blend_order='auto', unity_assets='') -> list[str]\n\nConverts a flare between "
        "flarekit presets and PlayCanvas, Babylon.js, three.js, Unity (sprite flares) and "
        "Unreal, Godot (post-process flares), as `flarekit convert` does (docs/interop.md); "
        "textures are written beside the output. Returns the warnings (one per feature that "
        "did not map); bad input raises ValueError with the CLI's message.\n\n"
        "from_, to: 'flarekit', 'playcanvas', 'babylon', 'three', 'unity', 'unreal', 'godot' "
        "(default: from the files).\naspect: screen width / height the engines' sizes are "
        "converted through, [0.1, 10].\nreference_height: frame height for pixel sizes "
        "(three.js), [16, 16384].\nunity_blend_order: 'auto', 'current' (SRP 12.0+) or "
        "'early' (SRP 12 previews).\nunity_assets: folder of a Unity project's .meta files.");
    m.def(
        "presets", [](const std::string& kind) { return presetNamesIn(kindNamed(kind).subdir); },
        py::arg("kind") = "sprite",
        "presets(kind='sprite') -> list[str]\n\nThe shipped presets' names: kind 'sprite', "
        "'postfx' or 'lens'.");
    m.def(
        "lenses", [] { return lensNames(); },
        "lenses() -> list[str]\n\nThe shipped lens prescriptions' names.");
    m.def(
        "lens_info",
        [](const std::string& nameOrPath) {
            const Lens lens = unwrap(loadLens(nameOrPath));
            const Paraxial p = paraxial(lens);
            py::dict out;
            out["name"] = lens.name;
            out["focal_length_mm"] = p.focalLength;
            out["f_number"] = p.fNumber;
            out["sensor_mm"] = py::make_tuple(lens.sensor.width, lens.sensor.height);
            // The sensor's width seen through the paraxial focal length: what a camera's
            // horizontal angle of view is matched against.
            out["horizontal_fov_deg"] =
                2.0 * std::atan(lens.sensor.width / (2.0 * p.focalLength)) * 180.0 / M_PI;
            out["blades"] = lens.aperture.blades;
            return out;
        },
        py::arg("lens"),
        "lens_info(lens) -> dict\n\nA prescription's paraxial focal length and f-number, its "
        "sensor (mm), the horizontal angle of view they make (degrees) and its iris blades.");
    m.def(
        "load_preset",
        [](const std::string& nameOrPath, const std::string& kind) {
            const Kind& k = kindNamed(kind);
            std::string path;
            const std::string text = unwrap(readPresetText(nameOrPath, k.subdir, path));
            check(k.validate(text, path));
            return jsonLoads(text);
        },
        py::arg("name"), py::arg("kind") = "sprite",
        "load_preset(name, kind='sprite') -> dict\n\nA shipped preset by name, or a JSON file, "
        "checked as the CLI checks it (ValueError with its message otherwise); kind 'sprite', "
        "'postfx' or 'lens'.");
    m.def(
        "validate_preset",
        [](const py::object& preset, const std::string& kind) {
            const Kind& k = kindNamed(kind);
            if (py::isinstance<py::str>(preset)) {
                std::string path;
                const std::string text = unwrap(readPresetText(py::str(preset), k.subdir, path));
                check(k.validate(text, path));
                return;
            }
            if (!py::isinstance<py::dict>(preset))
                throw py::value_error("preset: expected a dict or a name or path, got " +
                                      std::string(py::repr(preset)));
            check(k.validate(jsonText(preset), "<dict>"));
        },
        py::arg("preset"), py::arg("kind") = "sprite",
        "validate_preset(preset, kind='sprite') -> None\n\nA preset (dict, shipped name or JSON "
        "file) checked as the CLI checks it: ValueError with the CLI's one-line message.");

    static const std::string ghostsDoc =
        "lens_ghosts(lens, angle=(0, 0), f_number=0, **options) -> dict\n\nEvery two-reflection "
        "ghost of a distant point source at `angle` (degrees, x and y), brightest first, as "
        "`flarekit lens ghosts --json` prints it.\nKeywords from the parameter table:\n" +
        keywordDocs<LensToolOptions>(std::span(kLensToolParams).first(2), LensToolOptions{});
    m.def(
        "lens_ghosts",
        [](const std::string& lensName, const py::object& angle, double fNumber,
           const py::kwargs& kwargs) {
            LensToolOptions tool;
            Keywords k;
            k.table<LensToolOptions>(std::span(kLensToolParams).first(2), tool);
            k.read(kwargs);
            GhostQuery q;
            const auto a = angle.cast<std::pair<double, double>>();
            q.angleXDeg = a.first, q.angleYDeg = a.second;
            q.gridSide = tool.rays, q.ghostRays = tool.ghostRays;
            Result<std::string> json = internalError("not run");
            {
                py::gil_scoped_release release;
                auto lens = loadLens(lensName);
                if (lens && fNumber > 0) lens = stopDown(*lens, fNumber);
                Result<GhostReport> report =
                    lens ? analyseGhosts(*lens, q) : Result<GhostReport>(lens.error());
                if (report)
                    json = ghostReportJson(lens->name, *report);
                else
                    json = report.error();
            }
            return jsonLoads(unwrap(std::move(json)));
        },
        py::arg("lens"), py::arg("angle") = std::pair<double, double>{0, 0},
        py::arg("f_number") = 0.0, ghostsDoc.c_str());

    m.def(
        "elements",
        [](const std::string& preset, int cell) {
            if (cell < 32 || cell > 4096)
                throw py::value_error("cell: expected an integer in [32, 4096], got " +
                                      std::to_string(cell));
            Result<ContactSheet> sheet = internalError("not run");
            {
                py::gil_scoped_release release;
                auto p = loadPreset(preset);
                if (!p) {
                    sheet = p.error();
                } else if (Status s = checkFlareWork(*p, cell, cell, 1, preset); !s) {
                    sheet = s.error();
                } else {
                    sheet = renderContactSheet(*p, cell);
                }
            }
            return arrayFromImage(std::move(unwrap(std::move(sheet)).image), 4);
        },
        py::arg("preset") = kDefaultSpritePreset, py::arg("cell") = 256,
        "elements(preset='tanczos-classic', cell=256) -> ndarray\n\nA preset's elements as a "
        "labelled contact sheet (linear float32 H x W x 4), as `flarekit elements` draws it.");

    static const std::string visibilityDoc =
        "visibility(scene, method='raycast', *, variant='circle', **options) -> dict\n\nThe "
        "fraction of each light's disc visible from a scene's camera (a Scene dict or JSON "
        "file), as `flarekit visibility --json` prints it: method, coverage, in_frame, samples, "
        "latency_frames, cpu_ms, lights. Methods: " +
        visibilityMethodList() + ".\nKeywords from the parameter table:\n" +
        keywordDocs<RaycastOptions>(kRaycastParams, RaycastOptions{});
    m.def(
        "visibility",
        [](const py::object& sceneArg, const std::string& method, const std::string& variant,
           const py::kwargs& kwargs) {
            RaycastOptions raycast;
            Keywords k;
            k.table<RaycastOptions>(kRaycastParams, raycast);
            k.read(kwargs);
            if (method != "raycast" && !isGpuVisibilityMethod(method))
                throw py::value_error("method: expected one of " + visibilityMethodList() +
                                      ", got '" + method + "'");
            const bool fromFile = py::isinstance<py::str>(sceneArg);
            const std::string source = fromFile ? std::string(py::str(sceneArg)) : "<dict>";
            const std::string text = fromFile ? std::string() : jsonText(sceneArg);
            Result<VisibilityResult> r = internalError("not run");
            int latency = 0;
            {
                py::gil_scoped_release release;
                auto scene = fromFile ? loadScene(source) : parseScene(text, source);
                if (!scene) {
                    r = scene.error();
                } else if (method == "raycast") {
                    r = raycastVisibility(*scene, raycast);
                } else {
#if FLAREKIT_HAS_GL
                    SceneVisibilityOptions o;
                    o.source = source;
                    o.method = method;
                    o.methodOptions.textureMaskVariant = variant;
                    r = gpuSceneVisibility(*scene, o, &latency);
#else
                    (void)variant;
                    r = invalidInput("visibility method " + method +
                                     ": flarekit was built without OpenGL");
#endif
                }
            }
            return visibilityDict(unwrap(std::move(r)), latency);
        },
        py::arg("scene"), py::arg("method") = "raycast", py::kw_only(),
        py::arg("variant") = "circle", visibilityDoc.c_str());
}

}  // namespace flarekit::python
