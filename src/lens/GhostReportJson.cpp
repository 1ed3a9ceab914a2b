// SPDX-License-Identifier: Apache-2.0
// `lens ghosts --json`: the ghost report in the JSON its readers (scripts, the Python module)
// take, with each field explained beside the figures.
#include <nlohmann/json.hpp>

#include "flarekit/Lens.h"

namespace flarekit {

namespace {

nlohmann::json figureJson(const GhostFigure& g) {
    nlohmann::json j;
    if (g.first >= 0) j["surfaces"] = {g.first, g.second};
    j["center"] = {g.centerX, g.centerY};
    j["radius_mm"] = g.radius;
    j["radius50_mm"] = g.radius50;
    j["radius90_mm"] = g.radius90;
    j["on_sensor"] = g.onSensor;
    j["beam_share"] = g.beamShare;
    j["intensity"] = {g.intensity[0], g.intensity[1], g.intensity[2]};
    return j;
}

//! What each figure's field means, written into the JSON beside them.
nlohmann::json figureFields() {
    return {{"surfaces", "reflects at the first surface, then at the second (0 = front)"},
            {"center",
             "mm on the sensor plane: centroid of the rays landing on the sensor (d line); the "
             "median of the arriving rays when none lands"},
            {"radius_mm", "centre to the farthest ray reaching the sensor plane"},
            {"radius50_mm", "radius around the landing rays' median holding 50% of them"},
            {"radius90_mm", "radius around the landing rays' median holding 90% of them"},
            {"on_sensor", "share of the rays reaching the sensor plane that land on the sensor"},
            {"beam_share", "share of the rays entering the lens that reach the sensor plane"},
            {"intensity", "share of the light entering the first surface, R G B"}};
}

}  // namespace

std::string ghostReportJson(const std::string& lensName, const GhostReport& report) {
    nlohmann::json j;
    j["lens"] = lensName;
    j["focal_length_mm"] = report.focalLength;
    j["fields"] = figureFields();
    j["direct"] = figureJson(report.direct);
    j["ghosts"] = nlohmann::json::array();
    for (const GhostFigure& g : report.ghosts) j["ghosts"].push_back(figureJson(g));
    return j.dump(1);
}

}  // namespace flarekit
