// SPDX-License-Identifier: Apache-2.0
// The image jobs on numpy arrays (apply, postfx, lens_render), each the library's in-memory job
// (flarekit/job/PixelJob.h) run without the GIL, and the same jobs on files and sequences.
#include <optional>

#include <pybind11/stl.h>

#include "Bindings.h"
#include "Convert.h"
#include "Keywords.h"
#include "flarekit/job/PixelJob.h"
#if FLAREKIT_HAS_GL
#include "flarekit/gl/LensBackend.h"
#include "flarekit/gl/PostFxBackend.h"
#endif

namespace flarekit::python {

namespace {

std::optional<ToneOperator> toneKeyword(const py::object& tonemap) {
    if (tonemap.is_none()) return std::nullopt;
    const std::string name = py::str(tonemap);
    auto op = toneOperatorNamed(name);
    if (!op) throw py::value_error("tonemap: expected none, aces or filmic, got '" + name + "'");
    return op;
}

Point pointKeyword(const py::handle& value, const char* key) {
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) ||
        py::len(value) != 2)
        throw py::value_error(std::string(key) + ": expected (x, y) in pixels, got " +
                              std::string(py::repr(value)));
    const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
    return {s[0].cast<float>(), s[1].cast<float>()};
}

//! The job's result as numpy: the image alone, or (image, {layer: array}) with `layers`.
py::object jobResult(PixelOutput&& out, int channels, bool layers) {
    py::array image = arrayFromImage(std::move(out.image), channels);
    if (!layers) return image;
    py::dict named;
    for (auto& [name, layer] : out.layers)
        named[py::str(name)] = arrayFromImage(std::move(layer), 3);
    return py::make_tuple(image, named);
}

//! Runs `job` on the array without the GIL; warnings become Python warnings afterwards.
template <class Job>
py::object runPixels(const py::handle& array, bool displayReferred, bool layers, const Job& job) {
    PixelInput input;
    input.image = imageFromArray(array, "image", input.hasAlpha);
    input.displayReferred = displayReferred;
    const int channels = input.hasAlpha ? 4 : 3;
    CollectedEvents events;
    Result<PixelOutput> out = internalError("not run");
    {
        py::gil_scoped_release release;
        out = job(std::move(input), events.events());
    }
    events.emit();
    return jobResult(unwrap(std::move(out)), channels, layers);
}

//! expand_highlights: a gain through its table, or nothing.
std::optional<float> expandKeyword(const py::object& expand) {
    if (expand.is_none()) return std::nullopt;
    ExpandHighlights gain;
    setKeyword(kExpandHighlightsParams[0], expand, gain);
    return gain.gain;
}

std::shared_ptr<const PostFxBackend> postFxBackend(const std::string& name) {
    if (name == "cpu") return cpuPostFxBackend();
#if FLAREKIT_HAS_GL
    if (name == "gl") return gl::glPostFxBackend(gl::GlTransfer::Auto);
#else
    if (name == "gl") throw py::value_error("backend gl: flarekit was built without OpenGL");
#endif
    throw py::value_error("backend: expected cpu or gl, got '" + name + "'");
}

std::shared_ptr<const LensBackend> lensBackend(const std::string& name) {
    if (name == "cpu") return cpuLensBackend();
#if FLAREKIT_HAS_GL
    if (name == "gl") return gl::glLensBackend();
#else
    if (name == "gl") throw py::value_error("backend gl: flarekit was built without OpenGL");
#endif
    throw py::value_error("backend: expected cpu or gl, got '" + name + "'");
}

//! apply's keywords beyond the explicit ones: its table and the light finder's.
Keywords applyKeywords(ApplyOptions& o) {
    Keywords k;
    k.table<ApplyOptions>(kApplyParams, o)
        .table<LightSearchOptions>(kLightSearchParams, o.lightSearch);
    return k;
}

Keywords lensKeywords(LensJobOptions& o) {
    Keywords k;
    k.table<LensJobOptions>(kLensJobParams, o)
        .table<LensRenderOptions>(kLensRenderParams, o.render);
    return k;
}

void lensLight(const py::object& light, LensJobOptions& o) {
    if (py::isinstance<py::str>(light)) {
        const std::string mode = py::str(light);
        if (mode == "brightest")
            o.lightMode = LensLightMode::Brightest;
        else if (mode == "all")
            o.lightMode = LensLightMode::All;
        else
            throw py::value_error("light: expected 'brightest', 'all' or (x, y), got '" + mode +
                                  "'");
        return;
    }
    o.lightMode = LensLightMode::At;
    o.light = pointKeyword(light, "light");
}

//! A file job's summary: for a sequence, its frames.
py::dict reportDict(const JobReport& report) {
    py::dict d;
    d["sequence"] = report.sequence;
    if (report.sequence) {
        d["frames"] = report.shot.frames;
        d["wall_seconds"] = report.shot.wallSeconds;
    }
    return d;
}

template <class Run>
py::dict runFileJob(const Run& run) {
    CollectedEvents events;
    Result<JobReport> report = internalError("not run");
    {
        py::gil_scoped_release release;
        report = run(events.events());
    }
    events.emit();
    return reportDict(unwrap(std::move(report)));
}

const char* kApplyDoc =
    R"(apply(image, preset='tanczos-classic', light=None, *, layers=False, flare_only=False, tonemap=None, display_referred=False, **options)

A sprite preset's flare on a linear float32 H x W x 3|4 array, as `flarekit apply` draws it
(its float EXR output). `light`: (x, y) in pixels from the top-left (pixel centres at +0.5),
outside the frame allowed; None finds the lights in the image. `layers=True` returns
(image, {pass: array}) with each pass of the preset and the whole flare. `display_referred`:
the array was decoded from an 8/16-bit image (its white is the display's).
Keywords from the parameter tables:
)";

const char* kPostFxDoc =
    R"(postfx(image, preset='photo', *, layers=False, tonemap=None, backend='cpu', display_referred=False, exposure=None, threshold=None, knee=None, expand_highlights=None)

The post-process chain (ghosts, bloom, halo, streaks, starburst, dirt) on a linear float32
H x W x 3|4 array, as `flarekit postfx` writes a float EXR. `layers=True` returns (image,
{bloom, ghosts, halo, streaks, lens}). exposure, threshold and knee override the preset's.
`expand_highlights`: with display_referred, clipped pixels of the lights count as GAIN x white.
Keywords from the parameter tables:
)";

const char* kLensDoc =
    R"(lens_render(image, lens, light='brightest', *, layers=False, tonemap=None, backend='cpu', display_referred=False, **options)

A lens prescription's traced flare (ghosts, starburst, glare) on a linear float32 H x W x 3|4
array, as `flarekit lens render` writes a float EXR. `light`: 'brightest', 'all' or (x, y).
`layers=True` returns (image, {ghosts, starburst, glare, flare}).
Keywords from the parameter tables:
)";

}  // namespace

void addJobs(py::module_& m) {
    static const std::string applyDoc = std::string(kApplyDoc) +
                                        keywordDocs<ApplyOptions>(kApplyParams, ApplyOptions{}) +
                                        keywordDocs<LightSearchOptions>(kLightSearchParams, {});
    m.def(
        "apply",
        [](const py::handle& image, const std::string& preset, const py::object& light, bool layers,
           bool flareOnly, const py::object& tonemap, bool displayReferred,
           const py::kwargs& kwargs) {
            ApplyOptions o;
            o.preset = preset;
            if (!light.is_none()) o.light = pointKeyword(light, "light");
            o.flareOnly = flareOnly;
            o.tonemap = toneKeyword(tonemap);
            applyKeywords(o).read(kwargs);
            return runPixels(image, displayReferred, layers,
                             [&](PixelInput in, const JobEvents& e) {
                                 return applyPixels(o, std::move(in), e, layers);
                             });
        },
        py::arg("image"), py::arg("preset") = kDefaultSpritePreset, py::arg("light") = py::none(),
        py::kw_only(), py::arg("layers") = false, py::arg("flare_only") = false,
        py::arg("tonemap") = py::none(), py::arg("display_referred") = false, applyDoc.c_str());

    static const std::string postFxDoc =
        std::string(kPostFxDoc) + keywordDocs<ExpandHighlights>(kExpandHighlightsParams, {});
    m.def(
        "postfx",
        [](const py::handle& image, const std::string& preset, bool layers,
           const py::object& tonemap, const std::string& backend, bool displayReferred,
           std::optional<float> exposure, std::optional<float> threshold, std::optional<float> knee,
           const py::object& expand) {
            PostFxJobOptions o;
            o.preset = preset;
            o.tonemap = toneKeyword(tonemap);
            o.backend = postFxBackend(backend);
            o.exposure = exposure, o.threshold = threshold, o.knee = knee;
            o.expandHighlights = expandKeyword(expand);
            return runPixels(image, displayReferred, layers,
                             [&](PixelInput in, const JobEvents& e) {
                                 return postFxPixels(o, std::move(in), e, layers);
                             });
        },
        py::arg("image"), py::arg("preset") = kDefaultPostFxPreset, py::kw_only(),
        py::arg("layers") = false, py::arg("tonemap") = py::none(), py::arg("backend") = "cpu",
        py::arg("display_referred") = false, py::arg("exposure") = py::none(),
        py::arg("threshold") = py::none(), py::arg("knee") = py::none(),
        py::arg("expand_highlights") = py::none(), postFxDoc.c_str());

    static const std::string lensDoc =
        std::string(kLensDoc) + keywordDocs<LensJobOptions>(kLensJobParams, LensJobOptions{}) +
        keywordDocs<LensRenderOptions>(kLensRenderParams, LensRenderOptions{});
    m.def(
        "lens_render",
        [](const py::handle& image, const std::string& lens, const py::object& light, bool layers,
           const py::object& tonemap, const std::string& backend, bool displayReferred,
           const py::kwargs& kwargs) {
            LensJobOptions o;
            o.lens = lens;
            lensLight(light, o);
            o.tonemap = toneKeyword(tonemap);
            o.backend = lensBackend(backend);
            lensKeywords(o).read(kwargs);
            return runPixels(image, displayReferred, layers,
                             [&](PixelInput in, const JobEvents& e) {
                                 return lensPixels(o, std::move(in), e, layers);
                             });
        },
        py::arg("image"), py::arg("lens"), py::arg("light") = "brightest", py::kw_only(),
        py::arg("layers") = false, py::arg("tonemap") = py::none(), py::arg("backend") = "cpu",
        py::arg("display_referred") = false, lensDoc.c_str());

    // The file jobs: images or frame patterns (shot.####.exr) in and out, as the CLI runs them.
    m.def(
        "apply_file",
        [](const std::string& input, const std::string& output, const std::string& preset,
           const py::object& light, const std::string& lightTrack, const std::string& writeTrack,
           const std::string& layersDir, const py::object& tonemap, const py::kwargs& kwargs) {
            ApplyOptions o;
            o.input = input, o.output = output, o.preset = preset;
            if (!light.is_none()) o.light = pointKeyword(light, "light");
            o.lightTrack = lightTrack, o.writeTrack = writeTrack, o.layersDir = layersDir;
            o.tonemap = toneKeyword(tonemap);
            applyKeywords(o).read(kwargs);
            return runFileJob([&](const JobEvents& e) { return runApplyJob(o, e); });
        },
        py::arg("input"), py::arg("output"), py::arg("preset") = kDefaultSpritePreset,
        py::arg("light") = py::none(), py::kw_only(), py::arg("light_track") = "",
        py::arg("write_track") = "", py::arg("layers_dir") = "", py::arg("tonemap") = py::none(),
        "apply_file(input, output, preset, light=None, *, light_track='', write_track='', "
        "layers_dir='', tonemap=None, **options)\n\n`flarekit apply` on files: an image, or a "
        "frame pattern (shot.####.exr) in and out; light_track reads a light per frame, "
        "write_track saves the followed light. Keywords as flarekit.apply's.");
    m.def(
        "postfx_file",
        [](const std::string& input, const std::string& output, const std::string& preset,
           const std::string& layersDir, const py::object& tonemap, const std::string& backend,
           std::optional<float> exposure, std::optional<float> threshold, std::optional<float> knee,
           const py::object& expand) {
            PostFxJobOptions o;
            o.input = input, o.output = output, o.preset = preset, o.layersDir = layersDir;
            o.tonemap = toneKeyword(tonemap);
            o.backend = postFxBackend(backend);
            o.exposure = exposure, o.threshold = threshold, o.knee = knee;
            o.expandHighlights = expandKeyword(expand);
            return runFileJob([&](const JobEvents& e) { return runPostFxJob(o, e); });
        },
        py::arg("input"), py::arg("output"), py::arg("preset") = kDefaultPostFxPreset,
        py::kw_only(), py::arg("layers_dir") = "", py::arg("tonemap") = py::none(),
        py::arg("backend") = "cpu", py::arg("exposure") = py::none(),
        py::arg("threshold") = py::none(), py::arg("knee") = py::none(),
        py::arg("expand_highlights") = py::none(),
        "postfx_file(input, output, preset='photo', *, layers_dir='', tonemap=None, "
        "backend='cpu', exposure=None, threshold=None, knee=None, expand_highlights=None)\n\n"
        "`flarekit postfx` on files: an image or a frame pattern; keywords as flarekit.postfx's.");
    m.def(
        "lens_render_file",
        [](const std::string& input, const std::string& output, const std::string& lens,
           const py::object& light, const std::string& layersDir, const py::object& tonemap,
           const std::string& backend, const py::kwargs& kwargs) {
            LensJobOptions o;
            o.input = input, o.output = output, o.lens = lens, o.layersDir = layersDir;
            lensLight(light, o);
            o.tonemap = toneKeyword(tonemap);
            o.backend = lensBackend(backend);
            lensKeywords(o).read(kwargs);
            return runFileJob([&](const JobEvents& e) { return runLensJob(o, e); });
        },
        py::arg("input"), py::arg("output"), py::arg("lens"), py::arg("light") = "brightest",
        py::kw_only(), py::arg("layers_dir") = "", py::arg("tonemap") = py::none(),
        py::arg("backend") = "cpu",
        "lens_render_file(input, output, lens, light='brightest', *, layers_dir='', "
        "tonemap=None, backend='cpu', **options)\n\n`flarekit lens render` on files; keywords "
        "as flarekit.lens_render's.");
}

}  // namespace flarekit::python
