// SPDX-License-Identifier: Apache-2.0
#include "Keywords.h"

namespace flarekit::python {

void Keywords::read(const py::kwargs& kwargs) const {
    for (const auto& [key, value] : kwargs) {
        const std::string name = py::str(key);
        const Binder* binder = nullptr;
        for (const Binder& b : m_binders)
            if (b.key == name) binder = &b;
        if (!binder) {
            std::string known;
            for (const Binder& b : m_binders) known += (known.empty() ? "" : ", ") + b.key;
            throw py::value_error("unknown keyword '" + name + "' (known: " + known + ")");
        }
        if (!value.is_none()) binder->set(value);
    }
}

}  // namespace flarekit::python
