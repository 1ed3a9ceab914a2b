// SPDX-License-Identifier: Apache-2.0
// The Python module's two borders: numpy arrays to and from flarekit's images, and the
// library's errors as Python exceptions (ValueError for bad input, RuntimeError otherwise) with
// the option names spelt as Python keywords.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <mutex>
#include <string>
#include <vector>

#include "flarekit/Image.h"
#include "flarekit/Result.h"
#include "flarekit/job/Job.h"

namespace flarekit::python {

namespace py = pybind11;

//! The library's message with its CLI flags in Python's spelling: "--flux-mode" reads
//! "flux_mode", and the budget's "--max-memory or FLAREKIT_MAX_MEMORY" names
//! flarekit.set_max_memory.
std::string pythonSpelling(const std::string& message);

//! Raises `error` as ValueError (invalid input, a file that cannot be read or written: the
//! caller's to fix) or RuntimeError (internal failures, interruptions).
[[noreturn]] void raise(const Error& error);

template <class T>
T unwrap(Result<T>&& result) {
    if (!result) raise(result.error());
    return std::move(*result);
}
inline void check(const Status& status) {
    if (!status) raise(status.error());
}

//! A float32 H x W x {3,4} array (any strides; other float or integer dtypes are refused, as
//! are other shapes and empty arrays) copied into an image; `hasAlpha` says whether it had 4
//! channels. `what` names the argument in errors. The array is only read.
Image imageFromArray(const py::handle& array, const std::string& what, bool& hasAlpha);

//! `image` handed to numpy without a copy: H x W x 4, or H x W x 3 as a strided view of the
//! same RGBA memory when `channels` is 3. The array owns the image.
py::array arrayFromImage(Image&& image, int channels);

//! A dict (a preset, a scene, a generator config) as JSON text, through Python's json.dumps.
inline std::string jsonText(const py::handle& value) {
    return py::str(py::module_::import("json").attr("dumps")(value));
}

//! A job's events for a call made without the GIL: warnings and detail lines are kept and
//! given to Python's `warnings` (and the `info` list) once the call is back under the GIL.
class CollectedEvents {
  public:
    CollectedEvents();
    const JobEvents& events() const { return m_events; }
    //! Issues the kept warnings as Python UserWarnings (the GIL held).
    void emit() const;
    std::vector<std::string> infoLines() const;

  private:
    struct Lines {
        std::mutex mutex;
        std::vector<std::string> warnings, info;
    };
    std::shared_ptr<Lines> m_lines;
    JobEvents m_events;
};

}  // namespace flarekit::python
