// The demo's settings and its scene at a time, without GL: validation and the world the
// PSP demo and the tests share.
#include "demo/DemoWorld.h"
#include "flarekit/Demo.h"
#include "flarekit/Visibility.h"

namespace flarekit {

Scene demoScene(int width, int height, double t) {
    Scene s = demo::buildWorld(width, height);
    s.camera = demo::cameraAt(t);
    return s;
}

Status validateDemoSettings(const DemoSettings& settings) {
    if (settings.width < 16 || settings.height < 16 || settings.width > 16384 ||
        settings.height > 16384) {
        return invalidInput("size: expected each side in [16, 16384], got " +
                            std::to_string(settings.width) + "x" + std::to_string(settings.height));
    }
    if (Status s = validateParams<DemoSettings>(settings, kDemoParams, ""); !s) return s;
    if (settings.method != "raycast" && !isGpuVisibilityMethod(settings.method)) {
        return invalidInput("method: expected one of " + visibilityMethodList() + ", got '" +
                            settings.method + "'");
    }
    if (settings.conditionalRender && settings.method != "query") {
        return invalidInput(
            "conditional-render: needs --method query (the only method with an occlusion query), "
            "got '" +
            settings.method + "'");
    }
    return validateTemporalParams(settings.temporal);
}

}  // namespace flarekit
