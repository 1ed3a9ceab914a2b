// SPDX-License-Identifier: Apache-2.0
// The flare-data generator: one sample as numpy arrays (flarekit.synth.sample) and a shard of a
// set written to a folder (flarekit.synth.generate), both the library's (flarekit/Synth.h).
#include "flarekit/Synth.h"
#include "Bindings.h"
#include "Convert.h"

namespace flarekit::python {

namespace {

SynthConfig configFrom(const py::object& config) {
    if (config.is_none()) return {};
    if (!py::isinstance<py::dict>(config))
        throw py::value_error("config: expected a dict (synth.json's keys), got " +
                              std::string(py::repr(config)));
    return unwrap(parseSynthConfig(jsonText(config), "config"));
}

std::uint64_t whole(const py::handle& value, const char* key) {
    if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value) ||
        value.cast<py::int_>() < py::int_(0))
        throw py::value_error(std::string(key) + ": expected a whole number from 0, got " +
                              std::string(py::repr(value)));
    return value.cast<std::uint64_t>();
}

}  // namespace

void addSynth(py::module_& m) {
    m.def(
        "_synth_sample",
        [](const py::handle& index, const py::handle& seed, int width, int height,
           const py::object& config, bool centred) {
            const SynthConfig c = configFrom(config);
            const std::uint64_t i = whole(index, "index"), s = whole(seed, "seed");
            Result<SynthSample> sample = internalError("not run");
            {
                py::gil_scoped_release release;
                sample = synthSample(i, s, width, height, c, centred);
            }
            SynthSample out = unwrap(std::move(sample));
            py::dict layers;
            for (auto& [name, image] : out.layers)
                layers[py::str(name)] = arrayFromImage(std::move(image), 3);
            layers["label"] = py::module_::import("json").attr("loads")(out.label);
            return layers;
        },
        py::arg("index"), py::arg("seed"), py::arg("width"), py::arg("height"),
        py::arg("config") = py::none(), py::arg("centred") = false);
    m.def(
        "_synth_run",
        [](const py::handle& count, const std::string& out, const py::handle& seed, int width,
           int height, const py::object& config, const std::string& format, int shardIndex,
           int shardCount, int depth, bool resume) {
            SynthRunOptions o;
            o.count = whole(count, "count"), o.seed = whole(seed, "seed");
            o.out = out, o.width = width, o.height = height;
            o.config = configFrom(config);
            bool known = false;
            for (std::size_t f = 0; f < std::size(kSynthFormatNames); ++f)
                if (kSynthFormatNames[f] == format) o.format = SynthFormat(f), known = true;
            if (!known)
                throw py::value_error("format: expected flare7kpp, pairs or exr, got '" + format +
                                      "'");
            o.shardIndex = shardIndex, o.shardCount = shardCount, o.depth = depth;
            o.resume = resume;
            CollectedEvents events;
            Result<SynthRunReport> report = internalError("not run");
            {
                py::gil_scoped_release release;
                report = runSynthJob(o, events.events());
            }
            events.emit();
            const SynthRunReport r = unwrap(std::move(report));
            py::dict d;
            d["written"] = r.written;
            d["skipped"] = r.skipped;
            d["complete"] = r.complete;
            return d;
        },
        py::arg("count"), py::arg("out"), py::arg("seed"), py::arg("width"), py::arg("height"),
        py::arg("config") = py::none(), py::arg("format") = "exr", py::arg("shard_index") = 0,
        py::arg("shard_count") = 1, py::arg("depth") = 8, py::arg("resume") = false);
}

}  // namespace flarekit::python
