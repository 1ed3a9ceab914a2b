// SPDX-License-Identifier: Apache-2.0
// Every GPU visibility method against the ray-cast truth (256^2 rays) on the generated scenes
// of tests/support/OcclusionScenes.h; prints a markdown table of coverages and the maximum and
// mean absolute errors per method (the table in docs/occlusion.md).
//   usage: occlusion_accuracy [--rows]
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

#include "GpuMeasure.h"
#include "OcclusionScenes.h"
#include "flarekit/Visibility.h"
#include "flarekit/gl/GpuVisibility.h"
#include "flarekit/gl/HeadlessGl.h"

using namespace flarekit;

namespace {
std::vector<std::pair<std::string, GpuVisibilityOptions>> methods() {
    std::vector<std::pair<std::string, GpuVisibilityOptions>> m;
    for (const std::string& name : gpuVisibilityMethods()) {
        if (name == "texture-mask") {
            for (const char* v : {"square", "circle", "bilinear"}) {
                GpuVisibilityOptions o;
                o.textureMaskVariant = v;
                m.emplace_back(name + ":" + v, o);
            }
        } else {
            m.emplace_back(name, GpuVisibilityOptions{});
        }
    }
    const std::size_t singleSample = m.size();
    for (std::size_t i = 0; i < singleSample; ++i)
        m.emplace_back(m[i].first + ":msaa4", m[i].second);
    return m;
}

double measure(const std::string& label, const GpuVisibilityOptions& options, const Scene& scene) {
    auto coverage =
        test::measureGpuCoverage(label.substr(0, label.find(':')), scene,
                                 label.ends_with(":msaa4") ? 4 : 1, options.textureMaskVariant);
    return coverage ? *coverage : NAN;
}
}  // namespace

int main(int argc, char** argv) {
    const bool rows = argc > 1 && std::strcmp(argv[1], "--rows") == 0;
    auto gl = gl::HeadlessGl::create();
    if (!gl) {
        std::fprintf(stderr, "%s\n", gl.error().message.c_str());
        return 1;
    }
    auto cases = test::occlusionCases();
    cases.push_back({"subpixel-pole (not judged)", test::subpixelPole()});
    const auto ms = methods();
    std::map<std::string, double> maxErr, sumErr;
    int counted = 0;
    if (rows) {
        std::printf("| scene | disc px | raycast |");
        for (const auto& m : ms) std::printf(" %s |", m.first.c_str());
        std::printf("\n|---|---|---|");
        for (std::size_t i = 0; i < ms.size(); ++i) std::printf("---|");
        std::printf("\n");
    }
    for (const auto& c : cases) {
        RaycastOptions truthOptions;
        truthOptions.samplesPerSide = 256;
        const double truth = raycastVisibility(c.scene, truthOptions)->coverage;
        const double radiusPx = c.scene.sun.angularRadiusDeg * M_PI / 180 * (c.scene.height / 2.0) /
                                std::tan(c.scene.camera.fovYDeg * M_PI / 360);
        const double area = M_PI * radiusPx * radiusPx;  // for the table's "disc px" column
        const bool judged =
            test::judgedScene(c.scene) && c.name.find("not judged") == std::string::npos;
        if (rows) std::printf("| %s | %.0f | %.4f |", c.name.c_str(), area, truth);
        for (const auto& m : ms) {
            const double v = measure(m.first, m.second, c.scene);
            if (rows) std::printf(" %.4f |", v);
            if (judged) {
                const double e = std::abs(v - truth);
                maxErr[m.first] = std::max(maxErr[m.first], e);
                sumErr[m.first] += e;
            }
        }
        if (rows) std::printf("\n");
        counted += judged;
    }
    std::printf("\n%d of %zu scenes judged (disc fully in frame, >= 100 px). %s via %s\n\n",
                counted, cases.size(), (*gl)->renderer().c_str(), (*gl)->platform().c_str());
    std::printf("| method | max abs error | mean abs error |\n|---|---|---|\n");
    for (const auto& m : ms) {
        std::printf("| %s | %.4f | %.4f |\n", m.first.c_str(), maxErr[m.first],
                    sumErr[m.first] / std::max(1, counted));
    }
    return 0;
}
