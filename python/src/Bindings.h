// SPDX-License-Identifier: Apache-2.0
// The Python module's parts, each adding its functions to `flarekit._flarekit`.
#pragma once

#include <pybind11/pybind11.h>

namespace flarekit::python {

void addJobs(pybind11::module_& m);      //!< apply, postfx, lens_render and their file jobs
void addData(pybind11::module_& m);      //!< presets, lenses, scenes, visibility, elements
void addImages(pybind11::module_& m);    //!< read_image, write_image, blend8
void addSynth(pybind11::module_& m);     //!< the flare-data generator's sample
void addTemporal(pybind11::module_& m);  //!< TemporalFilter (coverage over frames)

}  // namespace flarekit::python
