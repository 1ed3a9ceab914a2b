// SPDX-License-Identifier: Apache-2.0
// `lens bake`: a lens compiled into a sprite preset, so the cheap sprite path and the engine API
// can wear its look. The ghosts come from the exact trace at one field angle; paraxially a
// ghost's centre moves in proportion to the light's image, which is what a sprite's position
// on the flare vector (t) assumes.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "flarekit/Lens.h"

namespace flarekit {

namespace {
//! The field at which the ghosts are measured: the light's image 30% of the sensor height from
//! the axis, off-axis enough for their positions to be well defined, small enough that most
//! ghosts are still whole.
constexpr double kBakeField = 0.3;
//! The brightest baked ghost's sprite intensity: the shipped hand-made presets put their
//! ghosts at 0.1-0.3 against a glow of 1; the others keep their traced ratios to it.
constexpr double kBrightestGhost = 0.35;
}  // namespace

Result<Preset> bakeLens(const Lens& lens, int ghostCount) {
    if (Status s = checkLensToolOption("ghosts", ghostCount); !s) return s.error();
    const double height = lens.sensor.height;
    const double focal = paraxial(lens).focalLength;
    GhostQuery q;
    q.angleXDeg = std::atan(kBakeField * height / focal) * 180 / M_PI;
    // A sprite's place and size need a fraction of a pixel, not the analysis's 0.1% of the
    // diagonal: 4,096 rays per ghost keep a bake of a 22-surface zoom under a second.
    q.ghostRays = 4096;
    auto report = analyseGhosts(lens, q);
    if (!report) return report.error();
    const double lightX = report->direct.centerX;

    struct Baked {
        ElementParams e;
        double brightness;
    };
    std::vector<Baked> baked;
    for (const GhostFigure& g : report->ghosts) {
        if (int(baked.size()) >= ghostCount) break;
        const double share = (g.intensity[0] + g.intensity[1] + g.intensity[2]) / 3;
        // The disc holding 90% of its rays: the farthest ray may be a grazing one metres away.
        const double size = g.radius90 / height;
        const double t = g.centerX / lightX;
        // A sprite covers at most 4 image heights, sits within t in [-8, 8]: ghosts past that
        // are washes over the whole frame, not shapes.
        if (g.rays == 0 || share <= 0 || size > 4 || size < 1e-4 || std::fabs(t) > 8) continue;
        Baked b;
        b.e = defaultElement(lens.aperture.blades >= 3 ? ElementType::Polygon : ElementType::Disc);
        b.e.blades = std::max(3, lens.aperture.blades);
        b.e.rotationDeg = float(lens.aperture.rotationDeg);
        b.e.t = float(t);
        b.e.size = float(size);
        const double top = std::max({g.intensity[0], g.intensity[1], g.intensity[2]});
        b.e.color = {float(g.intensity[0] / top), float(g.intensity[1] / top),
                     float(g.intensity[2] / top)};
        b.e.softness = 0.08f;
        // Its irradiance: its share of the light over its area on the image.
        b.brightness = share / (M_PI * size * size);
        baked.push_back(b);
    }
    if (baked.empty())
        return invalidInput(lens.name + ": no ghost at " + std::to_string(q.angleXDeg) +
                            " degrees fits a sprite");
    double brightest = 0;
    for (const Baked& b : baked) brightest = std::max(brightest, b.brightness);

    Preset preset;
    preset.name = lens.name + "-baked";
    std::ostringstream os;
    os << "baked from the lens " << lens.name << " ("
       << lens.source.substr(0, lens.source.find(';')) << "): its " << baked.size()
       << " brightest ghosts traced at " << q.angleXDeg
       << " degrees, their traced positions, sizes, colours and relative intensities";
    preset.description = os.str();
    ElementParams glow = defaultElement(ElementType::Glow);
    glow.t = 1, glow.size = 0.12f;
    preset.elements.push_back(glow);
    if (lens.aperture.blades >= 3) {
        // An n-bladed iris diffracts into n spikes when n is even, 2n when odd (each edge and
        // its opposite give the same pair when they are parallel).
        ElementParams spikes = defaultElement(ElementType::Streaks);
        spikes.t = 1, spikes.size = 0.3f;
        spikes.count = lens.aperture.blades % 2 ? 2 * lens.aperture.blades : lens.aperture.blades;
        spikes.rotationDeg = float(lens.aperture.rotationDeg);
        spikes.thickness = 0.006f, spikes.intensity = 0.6f;
        preset.elements.push_back(spikes);
    }
    for (Baked& b : baked) {
        b.e.intensity = float(kBrightestGhost * b.brightness / brightest);
        preset.elements.push_back(b.e);
    }
    if (Status s = validatePreset(preset); !s) return s.error();
    return preset;
}

}  // namespace flarekit
