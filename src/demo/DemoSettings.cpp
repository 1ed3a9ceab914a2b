// SPDX-License-Identifier: Apache-2.0
// The demo's settings and its scene at a time, without GL: validation and the world the
// PSP demo and the tests share.
#include "demo/DemoWorld.h"
#include "flarekit/Demo.h"
#include "flarekit/ParamText.h"
#include "flarekit/Visibility.h"

namespace flarekit {

Scene demoScene(int width, int height, double t) {
    Scene s = demo::buildWorld(width, height);
    s.camera = demo::cameraAt(t);
    return s;
}

Status validateDemoSettings(const DemoSettings& settings) {
    // Width and height are one "--size" to the user: one message naming both, with the range of
    // their kDemoParams rows.
    const Param<DemoSettings>& side = *findParam<DemoSettings>(kDemoParams, "width");
    const Param<DemoSettings>& height = *findParam<DemoSettings>(kDemoParams, "height");
    if (!numberFits(side, settings.width) || !numberFits(height, settings.height)) {
        return invalidInput("size: expected each side in " + formatParamRange(side.min, side.max) +
                            ", got " + std::to_string(settings.width) + "x" +
                            std::to_string(settings.height));
    }
    if (Status s = validateParams<DemoSettings>(settings, kDemoParams, ""); !s) return s;
    if (Status s = checkVisibilityMethod(settings.method); !s) return s;
    if (settings.conditionalRender && settings.method != "query") {
        return invalidInput(
            "conditional-render: needs --method query (the only method with an occlusion query), "
            "got '" +
            settings.method + "'");
    }
    return validateTemporalParams(settings.temporal);
}

}  // namespace flarekit
