// SPDX-License-Identifier: Apache-2.0
// `lens ghosts`: every two-reflection ghost of a distant point source through the exact tracer,
// the figures the contract names (centroid, radius and share of the light, per ghost).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Parallel.h"
#include "flarekit/Lens.h"
#include "flarekit/ParamText.h"
#include "lens/LensTrace.h"

namespace flarekit {

namespace {

struct Beam {
    std::vector<lens::Vec> origins;  //!< rays that enter the first surface's clear aperture
    lens::Vec dir;
};

//! The parallel beam over a grid of side x side points on the first surface's clear aperture.
Beam makeBeam(const lens::TraceLens& t, const GhostQuery& q) {
    Beam b;
    b.dir = lens::beamDirection(q.angleXDeg, q.angleYDeg);
    const double sa = t.surfaces.front().semiAperture;
    for (int iy = 0; iy < q.gridSide; ++iy) {
        for (int ix = 0; ix < q.gridSide; ++ix) {
            const double x = sa * (2.0 * (ix + 0.5) / q.gridSide - 1.0);
            const double y = sa * (2.0 * (iy + 0.5) / q.gridSide - 1.0);
            const lens::Vec o = lens::beamOrigin(t, b.dir, x, y);
            if (lens::entersLens(t, o, b.dir)) b.origins.push_back(o);
        }
    }
    return b;
}

GhostFigure figure(const Lens& lens, const std::vector<lens::TraceLens>& traces,
                   const std::vector<Beam>& beams, int first, int second) {
    GhostFigure g;
    g.first = first, g.second = second;
    const auto path = lens::ghostPath(int(lens.surfaces.size()), first, second);
    // traces[0] is the d line (geometry), traces[1..3] the R, G, B wavelengths (intensity).
    std::vector<std::array<double, 2>> hits;
    for (const lens::Vec& o : beams[0].origins) {
        const lens::RayResult r = lens::traceRay(traces[0], path, o, beams[0].dir, true);
        if (r.alive) hits.push_back({r.x, r.y});
    }
    g.rays = int(hits.size());
    if (!hits.empty()) {
        for (const auto& h : hits) g.centerX += h[0], g.centerY += h[1];
        g.centerX /= double(hits.size()), g.centerY /= double(hits.size());
        for (const auto& h : hits)
            g.radius = std::max(g.radius, std::hypot(h[0] - g.centerX, h[1] - g.centerY));
    }
    for (std::size_t c = 0; c < 3; ++c) {
        const Beam& b = beams[c + 1];
        double sum = 0;
        for (const lens::Vec& o : b.origins) {
            const lens::RayResult r = lens::traceRay(traces[c + 1], path, o, b.dir, true);
            if (r.alive) sum += r.throughput;
        }
        g.intensity[c] = b.origins.empty() ? 0.0 : sum / double(b.origins.size());
    }
    return g;
}

}  // namespace

Status checkLensToolOption(std::string_view key, int value) {
    const Param<LensToolOptions>* p = findParam<LensToolOptions>(kLensToolParams, key);
    if (!p) return internalError("no lens tool option '" + std::string(key) + "'");
    if (numberFits(*p, double(value))) return Ok{};
    return invalidInput("--" + std::string(key) + ": expected " + expectedText(*p) + ", got " +
                        std::to_string(value));
}

Result<GhostReport> analyseGhosts(const Lens& lens, const GhostQuery& query) {
    if (!(std::fabs(query.angleXDeg) < 89.0 && std::fabs(query.angleYDeg) < 89.0))
        return invalidInput("--angle: expected field angles within (-89, 89) degrees");
    if (Status s = checkLensToolOption("rays", query.gridSide); !s) return s.error();
    std::vector<lens::TraceLens> traces{lens::prepareTrace(lens, kLineD)};
    for (const double w : kRgbWavelengthsNm) traces.push_back(lens::prepareTrace(lens, w));
    std::vector<Beam> beams;
    for (const auto& t : traces) beams.push_back(makeBeam(t, query));
    GhostReport report;
    report.focalLength = paraxial(lens).focalLength;
    report.direct = figure(lens, traces, beams, -1, -1);
    if (report.direct.rays == 0) {
        std::ostringstream os;
        os << lens.name << ": no ray reaches the sensor at field angle " << query.angleXDeg << ","
           << query.angleYDeg << " degrees (the lens vignettes it completely)";
        return invalidInput(os.str());
    }
    std::vector<std::array<int, 2>> pairs;
    const int n = int(lens.surfaces.size());
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < i; ++j) {
            if (lens::canReflect(traces[0], i) && lens::canReflect(traces[0], j))
                pairs.push_back({i, j});
        }
    }
    report.ghosts.resize(pairs.size());
    parallelFor(0, int(pairs.size()), 1, [&](int begin, int end) {
        for (int k = begin; k < end; ++k)
            report.ghosts[std::size_t(k)] =
                figure(lens, traces, beams, pairs[std::size_t(k)][0], pairs[std::size_t(k)][1]);
    });
    std::stable_sort(report.ghosts.begin(), report.ghosts.end(),
                     [](const GhostFigure& a, const GhostFigure& b) {
                         return a.intensity[0] + a.intensity[1] + a.intensity[2] >
                                b.intensity[0] + b.intensity[1] + b.intensity[2];
                     });
    return report;
}

}  // namespace flarekit
