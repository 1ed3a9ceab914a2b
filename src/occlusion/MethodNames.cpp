// SPDX-License-Identifier: Apache-2.0
// The GPU method names, from the registry, for the GL-free core: validation and messages work
// the same in a build without OpenGL.
#include <algorithm>

#include "flarekit/Visibility.h"
#include "occlusion/MethodRegistry.h"

namespace flarekit {

const std::vector<std::string>& gpuVisibilityMethods() {
#define FLAREKIT_METHOD_NAME(name, factory) name,
    static const std::vector<std::string> names = {FLAREKIT_GPU_METHODS(FLAREKIT_METHOD_NAME)};
#undef FLAREKIT_METHOD_NAME
    return names;
}

bool isGpuVisibilityMethod(const std::string& name) {
    const auto& names = gpuVisibilityMethods();
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::string visibilityMethodList() {
    std::string list = "raycast";
    for (const std::string& n : gpuVisibilityMethods()) list += " " + n;
    return list;
}

Status checkVisibilityMethod(const std::string& name) {
    if (name == "raycast" || isGpuVisibilityMethod(name)) return Ok{};
    return invalidInput("method: expected one of " + visibilityMethodList() + ", got '" + name +
                        "'");
}

}  // namespace flarekit
