// SPDX-License-Identifier: Apache-2.0
// `lens sheet`: the lens in cross-section (surfaces, glass, stop, sensor) with the rays of the
// direct image and of its brightest ghost, above the lens's flare at three field angles.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/codecs/OiioModule.h"
#include "flarekit/Lens.h"
#include "flarekit/Limits.h"
#include "lens/LensTrace.h"

namespace flarekit {

namespace {

//! The drawing's share of the sheet's height; the three flare panels take the rest.
constexpr double kSectionShare = 0.62;
//! Meridional rays drawn per beam.
constexpr int kRaysPerBeam = 9;

struct Canvas {
    Image& image;
    double scale = 1, z0 = 0, yMid = 0;  //!< mm to pixels: x = (z - z0) scale, y = yMid - y scale
    int top = 0, bottom = 0;             //!< rows the drawing may use

    void add(int x, int y, const Rgb& c) {
        if (x < 0 || x >= image.width() || y < top || y >= bottom) return;
        Rgba& p = image.at(x, y);
        p.r += c[0], p.g += c[1], p.b += c[2];
    }
    double px(double z) const { return (z - z0) * scale; }
    double py(double y) const { return yMid - y * scale; }
    //! A line from (z, y) to (z, y) in mm, one sample per pixel of its length.
    void line(double za, double ya, double zb, double yb, const Rgb& c) {
        const double x0 = px(za), y0 = py(ya), x1 = px(zb), y1 = py(yb);
        const int steps =
            int(std::min(1e5, std::ceil(std::max(std::fabs(x1 - x0), std::fabs(y1 - y0))))) + 1;
        for (int i = 0; i <= steps; ++i) {
            const double t = double(i) / steps;
            add(int(std::floor(x0 + (x1 - x0) * t)), int(std::floor(y0 + (y1 - y0) * t)), c);
        }
    }
};

void drawLens(const Lens& lens, const lens::TraceLens& t, double reach, Canvas& cv) {
    const Rgb white{0.9f, 0.9f, 0.9f}, glass{0.05f, 0.09f, 0.14f}, stop{0.9f, 0.55f, 0.2f};
    for (std::size_t i = 0; i < t.surfaces.size(); ++i) {
        const lens::TraceSurface& s = t.surfaces[i];
        if (s.stop) {
            // The iris: blades from the stop's radius out to the barrel.
            cv.line(s.z, s.semiAperture, s.z, reach * 1.08, stop);
            cv.line(s.z, -s.semiAperture, s.z, -reach * 1.08, stop);
            continue;
        }
        // Glass between this surface and the next: filled row by row between the two sags.
        if (lens.surfaces[i].nd > 1.0 && i + 1 < t.surfaces.size()) {
            const lens::TraceSurface& next = t.surfaces[i + 1];
            const double h = std::min(s.semiAperture, next.semiAperture);
            for (int row = int(cv.py(h)); row <= int(cv.py(-h)); ++row) {
                const double y = (cv.yMid - row) / cv.scale;
                const int a = int(cv.px(s.z + lens::surfaceSag(s.radius, y))),
                          b = int(cv.px(next.z + lens::surfaceSag(next.radius, y)));
                for (int x = a; x <= b; ++x) cv.add(x, row, glass);
            }
        }
        const int n = 200;
        for (int k = 0; k < n; ++k) {
            const double ya = s.semiAperture * (2.0 * k / n - 1),
                         yb = s.semiAperture * (2.0 * (k + 1) / n - 1);
            cv.line(s.z + lens::surfaceSag(s.radius, ya), ya, s.z + lens::surfaceSag(s.radius, yb),
                    yb, white);
        }
    }
    cv.line(t.sensorZ, -lens.sensor.height / 2, t.sensorZ, lens.sensor.height / 2, white);
}

//! A fan of meridional rays of the beam at `angleDeg` along `path`, drawn where they pass.
void drawBeam(const lens::TraceLens& t, const std::vector<lens::PathStep>& path, double angleDeg,
              const Rgb& colour, Canvas& cv) {
    const lens::Vec dir = lens::beamDirection(0, angleDeg);
    const double sa = t.surfaces.front().semiAperture;
    for (int k = 0; k < kRaysPerBeam; ++k) {
        const double y = sa * (2.0 * (k + 0.5) / kRaysPerBeam - 1);
        std::vector<lens::Vec> points;
        const lens::RayResult r =
            lens::traceRay(t, path, lens::beamOrigin(t, dir, 0, y), dir, true, &points);
        if (!r.alive) continue;
        for (std::size_t i = 1; i < points.size(); ++i)
            cv.line(points[i - 1].z, points[i - 1].y, points[i].z, points[i].y, colour);
    }
}

}  // namespace

Result<Image> renderLensSheet(const Lens& lens, int width) {
    if (Status s = checkLensToolOption("width", width); !s) return s.error();
    const int height = width * 9 / 16;
    if (Status s = checkMemory("lens sheet: " + std::to_string(width) + " px wide",
                               double(width) * height * 16.0 * 4);
        !s)
        return s.error();
    Image sheet(width, height);
    sheet.fill({0.f, 0.f, 0.f, 1.f});
    const lens::TraceLens t = lens::prepareTrace(lens, kLineD);
    const Paraxial p = paraxial(lens);

    // The section: z from a margin before the first surface to past the sensor, fitted.
    const int sectionHeight = int(height * kSectionShare);
    double reach = lens.sensor.height / 2;
    for (const lens::TraceSurface& s : t.surfaces) reach = std::max(reach, s.semiAperture);
    const double length = t.sensorZ;
    Canvas cv{sheet};
    cv.top = 0, cv.bottom = sectionHeight;
    cv.scale = std::min(width * 0.9 / (length * 1.1), sectionHeight * 0.8 / (2.2 * reach));
    cv.z0 = -((width / cv.scale) - length) / 2;
    cv.yMid = sectionHeight / 2.0;
    drawLens(lens, t, reach, cv);
    const double field = std::atan(0.3 * lens.sensor.height / p.focalLength) * 180 / M_PI;
    const int n = int(lens.surfaces.size());
    drawBeam(t, lens::ghostPath(n, -1, -1), 0, {0.5f, 0.45f, 0.1f}, cv);
    drawBeam(t, lens::ghostPath(n, -1, -1), field, {0.1f, 0.45f, 0.5f}, cv);
    GhostQuery q;
    q.angleYDeg = field;
    q.ghostRays = 0;  // the brightest path is all it draws
    auto report = analyseGhosts(lens, q);
    if (!report) return report.error();
    if (!report->ghosts.empty()) {
        const GhostFigure& g = report->ghosts.front();
        drawBeam(t, lens::ghostPath(n, g.first, g.second), field, {0.6f, 0.15f, 0.5f}, cv);
    }

    // The flare of a point source at three field angles, each in its own panel.
    const int panelW = width / 3, panelH = height - sectionHeight;
    LensRenderOptions o;
    o.ghosts = 32;  // at the flux level: every lens's ghosts show, whatever its coating
    for (int k = 0; k < 3; ++k) {
        LensLight light;
        light.x = panelW * (0.5 + 0.18 * k), light.y = panelH * (0.5 - 0.12 * k);
        light.energy = {2e5, 2e5, 2e5};
        auto layers = renderLensFlare(lens, panelW, panelH, {light}, o);
        if (!layers) return layers.error();
        for (int y = 0; y < panelH; ++y) {
            for (int x = 0; x < panelW; ++x) {
                const Rgba& a = layers->ghosts.at(x, y);
                const Rgba& b = layers->starburst.at(x, y);
                const Rgba& c = layers->glare.at(x, y);
                Rgba& out = sheet.at(k * panelW + x, sectionHeight + y);
                // A gentle roll-off so the light's core does not flatten the panel.
                const auto roll = [](float v) { return v / (1.f + v); };
                out.r = roll(a.r + b.r + c.r), out.g = roll(a.g + b.g + c.g),
                out.b = roll(a.b + b.b + c.b);
            }
        }
    }
    if (const codec::OiioModule* text = codec::oiioModule()) {
        std::ostringstream title;
        title.precision(4);
        title << lens.name << "   f = " << p.focalLength << " mm   F/" << p.fNumber << "   "
              << lens.surfaces.size() << " surfaces   yellow: on axis, cyan: " << field
              << " deg, magenta: its brightest ghost";
        const float colour[] = {0.85f, 0.85f, 0.85f, 1.f};
        const int size = std::max(12, width / 80);
        text->renderText(sheet.data(), width, height, size / 2, size + size / 2, title.str(), size,
                         codec::kLabelFontFile, colour);
    }
    return sheet;
}

}  // namespace flarekit
