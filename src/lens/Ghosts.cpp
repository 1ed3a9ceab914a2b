// SPDX-License-Identifier: Apache-2.0
// `lens ghosts`: every two-reflection ghost of a distant point source through the exact tracer,
// the figures the contract names (centroid, radius and share of the light, per ghost).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Parallel.h"
#include "core/Random.h"
#include "flarekit/Lens.h"
#include "flarekit/ParamText.h"
#include "lens/LensTrace.h"

namespace flarekit {

namespace {

using lens::Beam;

//! Whether a sensor-plane point lands on the sensor.
bool lands(const std::array<double, 2>& h, const LensSensor& sensor) {
    return std::fabs(h[0]) <= sensor.width / 2 && std::fabs(h[1]) <= sensor.height / 2;
}

//! The d-line rays of a ghost that reach the sensor plane, and how many arrive and enter in all.
struct Arrivals {
    std::vector<std::array<double, 2>> hits;  //!< the traced rays that arrived
    //! Rays arriving and entering, counted at the finest sampling (a cell left coarse stands
    //! for its k^2 points).
    double arriving = 0, entering = 0;
};
//! 32 x 32 points per cell: a 64-ray grid refined to 2,048 rays per diameter.
constexpr int kMaxRefine = 32;
//! Cells within two of a marked one are refined: a ghost whose light crosses the pupil in thin
//! slivers (near a caustic or total internal reflection) has marked cells up to three apart,
//! and one ring left parts of it untraced (the Nikon zoom's ghost 16-11 at 1 degree moved by
//! 0.2% of the diagonal).
constexpr int kBorder = 2;

//! The ghost `path` through the beam. With a `target`, the cells within kBorder of one holding a
//! ray landing on the sensor (or arriving, when none lands) are traced again at k x k jittered
//! points, k the smallest that gives about `target` such rays (at most kMaxRefine): a ghost's
//! centre converges with its own landing rays, not the beam's, and a ghost carrying 1% of the
//! light has 1% of the beam's rays, a wash mostly off the sensor fewer still.
Arrivals traceArrivals(const lens::TraceLens& t, const Beam& b,
                       const std::vector<lens::PathStep>& path, const LensSensor& sensor,
                       int target) {
    Arrivals a;
    const int n = b.cellsPerSide;
    std::vector<char> arrived(std::size_t(n) * std::size_t(n), 0), landed(arrived.size(), 0);
    std::vector<std::array<double, 2>> coarse(arrived.size());
    int landings = 0;
    for (std::size_t i = 0; i < b.origins.size(); ++i) {
        const lens::RayResult r = lens::traceRay(t, path, b.origins[i], b.dir, true);
        if (!r.alive) continue;
        const std::size_t cell = std::size_t(b.cells[i]);
        a.hits.push_back({r.x, r.y});
        arrived[cell] = 1, coarse[cell] = {r.x, r.y};
        if (lands(a.hits.back(), sensor)) landed[cell] = 1, ++landings;
    }
    a.arriving = double(a.hits.size());
    a.entering = double(b.origins.size());
    const std::vector<char>& marked = landings > 0 ? landed : arrived;
    const int count = landings > 0 ? landings : int(a.hits.size());
    if (target <= 0 || count == 0 || count >= target) return a;
    const int k = std::min(kMaxRefine, int(std::ceil(std::sqrt(double(target) / count))));
    const auto near = [&](int cell) {
        const int cx = cell % n, cy = cell / n;
        for (int y = std::max(0, cy - kBorder); y <= std::min(n - 1, cy + kBorder); ++y)
            for (int x = std::max(0, cx - kBorder); x <= std::min(n - 1, cx + kBorder); ++x)
                if (marked[std::size_t(y * n + x)]) return true;
        return false;
    };
    Arrivals fine;
    fine.entering = a.entering * k * k;
    for (int cell = 0; cell < n * n; ++cell) {
        if (!near(cell)) {
            // Off the sensor and away from it: its coarse ray stands for the cell.
            if (arrived[std::size_t(cell)]) {
                fine.hits.push_back(coarse[std::size_t(cell)]);
                fine.arriving += k * k;
            }
            continue;
        }
        // A second stream, so the refined points are not the beam's own.
        SplitMix64 random(0x5EEDull << 32 | std::uint64_t(cell));
        for (int sy = 0; sy < k; ++sy) {
            for (int sx = 0; sx < k; ++sx) {
                const double fx = (sx + random.nextDouble()) / k,
                             fy = (sy + random.nextDouble()) / k;
                const lens::Vec o = b.origin(t, cell, fx, fy);
                if (!lens::entersLens(t, o, b.dir)) continue;
                const lens::RayResult r = lens::traceRay(t, path, o, b.dir, true);
                if (r.alive) fine.hits.push_back({r.x, r.y}), fine.arriving += 1;
            }
        }
    }
    return fine;
}

//! The value below which a share q of `v` lies (nearest rank; v is reordered).
double quantile(std::vector<double>& v, double q) {
    const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size())));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

//! Where the ghost's rays lie on `sensor`: the GhostFigure fields of position and share. The
//! landing rays are all traced at one sampling (refinement covers every cell near one), so
//! their centroid and percentiles weigh each alike.
void placeFigure(const Arrivals& a, const LensSensor& sensor, GhostFigure& g) {
    g.rays = int(a.hits.size());
    if (a.entering > 0) g.beamShare = a.arriving / a.entering;
    if (a.hits.empty()) return;
    std::vector<std::array<double, 2>> landed;
    for (const auto& h : a.hits)
        if (lands(h, sensor)) landed.push_back(h);
    g.onSensor = double(landed.size()) / a.arriving;
    const auto& spread = landed.empty() ? a.hits : landed;
    std::vector<double> xs, ys;
    for (const auto& h : spread) xs.push_back(h[0]), ys.push_back(h[1]);
    const double medianX = quantile(xs, 0.5), medianY = quantile(ys, 0.5);
    if (landed.empty()) {
        g.centerX = medianX, g.centerY = medianY;
    } else {
        for (const auto& h : landed) g.centerX += h[0], g.centerY += h[1];
        g.centerX /= double(landed.size()), g.centerY /= double(landed.size());
    }
    std::vector<double> radii;
    // sqrt, not std::hypot (glibc's is slow): sensor-plane millimetres cannot overflow.
    for (const auto& h : spread) {
        const double dx = h[0] - medianX, dy = h[1] - medianY;
        radii.push_back(std::sqrt(dx * dx + dy * dy));
    }
    g.radius50 = quantile(radii, 0.5), g.radius90 = quantile(radii, 0.9);
    for (const auto& h : a.hits)
        g.radius = std::max(g.radius, std::sqrt((h[0] - g.centerX) * (h[0] - g.centerX) +
                                                (h[1] - g.centerY) * (h[1] - g.centerY)));
}

GhostFigure figure(const Lens& lens, const std::vector<lens::TraceLens>& traces, const Beam& beam,
                   int first, int second, int ghostRays) {
    GhostFigure g;
    g.first = first, g.second = second;
    const auto path = lens::ghostPath(int(lens.surfaces.size()), first, second);
    // traces[0] is the d line (geometry), traces[1..3] the R, G, B wavelengths (intensity).
    placeFigure(traceArrivals(traces[0], beam, path, lens.sensor, ghostRays), lens.sensor, g);
    for (std::size_t c = 0; c < 3; ++c) {
        double sum = 0;
        for (const lens::Vec& o : beam.origins) {
            const lens::RayResult r = lens::traceRay(traces[c + 1], path, o, beam.dir, true);
            if (r.alive) sum += r.throughput;
        }
        g.intensity[c] = beam.origins.empty() ? 0.0 : sum / double(beam.origins.size());
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
    if (Status s = checkLensToolOption("ghost_rays", query.ghostRays); !s) return s.error();
    std::vector<lens::TraceLens> traces{lens::prepareTrace(lens, kLineD)};
    for (const double w : kRgbWavelengthsNm) traces.push_back(lens::prepareTrace(lens, w));
    // Which rays enter depends on the first surface's shape alone, not on the wavelength: one
    // beam serves every trace.
    const Beam beam = lens::makeBeam(
        traces[0], lens::beamDirection(query.angleXDeg, query.angleYDeg), query.gridSide);
    GhostReport report;
    report.focalLength = paraxial(lens).focalLength;
    report.direct = figure(lens, traces, beam, -1, -1, query.ghostRays);
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
            report.ghosts[std::size_t(k)] = figure(lens, traces, beam, pairs[std::size_t(k)][0],
                                                   pairs[std::size_t(k)][1], query.ghostRays);
    });
    // A light outside the field still flares, as long as some path reaches the sensor plane.
    const bool anyGhost = std::any_of(report.ghosts.begin(), report.ghosts.end(),
                                      [](const GhostFigure& g) { return g.rays > 0; });
    if (report.direct.rays == 0 && !anyGhost) {
        std::ostringstream os;
        os << lens.name << ": no ray reaches the sensor at field angle " << query.angleXDeg << ","
           << query.angleYDeg << " degrees (the lens vignettes it completely)";
        return invalidInput(os.str());
    }
    std::stable_sort(report.ghosts.begin(), report.ghosts.end(),
                     [](const GhostFigure& a, const GhostFigure& b) {
                         return a.intensity[0] + a.intensity[1] + a.intensity[2] >
                                b.intensity[0] + b.intensity[1] + b.intensity[2];
                     });
    return report;
}

}  // namespace flarekit
