// SPDX-License-Identifier: Apache-2.0
// flarekit.TemporalFilter: the library's temporal filter of a light's coverage over frames
// (attack, release, edge fade, exposure adaptation), for front ends that render frame by frame
// (the Blender add-on).
#include <string>

#include "Bindings.h"
#include "Keywords.h"
#include "flarekit/Temporal.h"

namespace flarekit::python {

namespace {

const char* kTemporalDoc = R"(TemporalFilter(**params)

A light's coverage smoothed over frames as flarekit's shots smooth it: attack when the light
appears, release when it is hidden, the edge fade near the frame's border and the exposure's
adaptation, each frame-rate independent. update() once per frame, in order.
Keywords from the parameter table (Python spellings):
)";

}  // namespace

void addTemporal(py::module_& m) {
    static const std::string doc =
        std::string(kTemporalDoc) + keywordDocs<TemporalParams>(kTemporalParams, {});
    py::class_<TemporalFilter>(m, "TemporalFilter", doc.c_str())
        .def(py::init([](const py::kwargs& kwargs) {
            TemporalParams params;
            Keywords().table<TemporalParams>(kTemporalParams, params).read(kwargs);
            if (Status s = validateTemporalParams(params); !s)
                throw py::value_error(s.error().message);
            return TemporalFilter(params);
        }))
        .def(
            "update",
            [](TemporalFilter& filter, double coverage, const py::object& light, bool inFront,
               int width, int height, double dt) {
                if (!(coverage >= 0 && coverage <= 1))
                    throw py::value_error("coverage: expected a number in [0, 1]");
                if (!(dt >= 0) || width < 1 || height < 1)
                    throw py::value_error("dt, width, height: expected dt >= 0 and a frame size");
                const auto xy = light.cast<std::pair<double, double>>();
                const TemporalState s = filter.update(
                    coverage, Point{float(xy.first), float(xy.second)}, inFront, width, height, dt);
                py::dict out;
                out["coverage"] = s.coverage;
                out["edge_fade"] = s.edgeFade;
                out["exposure"] = s.exposure;
                out["flare_weight"] = s.flareWeight;
                return out;
            },
            py::arg("coverage"), py::arg("light"), py::arg("in_front"), py::arg("width"),
            py::arg("height"), py::arg("dt"),
            "update(coverage, light, in_front, width, height, dt) -> dict\n\nOne frame: the "
            "measured coverage (0-1), the light's pixel (x, y), whether it is in front of the "
            "camera, the frame size and the seconds since the previous frame. Returns coverage "
            "(smoothed), edge_fade, exposure and flare_weight (coverage x edge_fade).");
}

}  // namespace flarekit::python
