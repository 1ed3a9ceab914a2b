// SPDX-License-Identifier: Apache-2.0
// The exact tracer (see LensTrace.h).
#include "lens/LensTrace.h"

#include <algorithm>
#include <cmath>

#include "core/Random.h"

namespace flarekit::lens {

namespace {

Vec operator+(Vec a, Vec b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Vec operator*(Vec a, double k) {
    return {a.x * k, a.y * k, a.z * k};
}
double dot(Vec a, Vec b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

//! Distance along dir to the surface's cap on the vertex side; negative when it misses.
double intersect(const TraceSurface& s, Vec o, Vec d) {
    if (s.radius == 0.0) return std::fabs(d.z) < 1e-15 ? -1.0 : (s.z - o.z) / d.z;
    const Vec c{0, 0, s.z + s.radius};
    const Vec oc{o.x - c.x, o.y - c.y, o.z - c.z};
    const double b = dot(oc, d), cc = dot(oc, oc) - s.radius * s.radius;
    const double disc = b * b - cc;
    if (disc < 0) return -1.0;
    const double root = std::sqrt(disc);
    // Of the sphere's two crossings, the one on the vertex's hemisphere: (p - c).z has the
    // sign opposite to the radius there.
    for (const double t : {-b - root, -b + root}) {
        if (t <= 1e-9) continue;
        const double pz = o.z + t * d.z - c.z;
        if (pz * s.radius < 0) return t;
    }
    return -1.0;
}

}  // namespace

TraceLens prepareTrace(const Lens& lens, double lambdaNm) {
    TraceLens t;
    t.lambdaNm = lambdaNm;
    t.aperture = lens.aperture;
    t.iris = makeIris(lens.aperture);
    double z = 0;
    for (const LensSurface& s : lens.surfaces) {
        TraceSurface ts;
        ts.z = z, ts.radius = s.radius, ts.semiAperture = s.semiAperture, ts.stop = s.stop;
        ts.nAfter = refractiveIndex(s, lambdaNm);
        ts.coating = s.coating;
        t.surfaces.push_back(ts);
        z += s.thickness;
    }
    t.sensorZ = z;
    for (std::size_t i = 0; i < t.surfaces.size(); ++i) {
        TraceSurface& ts = t.surfaces[i];
        const double before = t.nBefore(i);
        ts.reflectFromFront.resize(kReflectanceSteps + 1);
        ts.reflectFromBack.resize(kReflectanceSteps + 1);
        for (int k = 0; k <= kReflectanceSteps; ++k) {
            const double c = double(k) / kReflectanceSteps;
            ts.reflectFromFront[std::size_t(k)] =
                float(interfaceReflectance(before, ts.nAfter, c, ts.coating, lambdaNm));
            ts.reflectFromBack[std::size_t(k)] =
                float(interfaceReflectance(ts.nAfter, before, c, ts.coating, lambdaNm));
        }
    }
    return t;
}

bool entersLens(const TraceLens& lens, Vec o, Vec d) {
    const TraceSurface& s = lens.surfaces.front();
    const double t = intersect(s, o, d);
    if (t < 0) return false;
    const Vec p = o + d * t;
    return std::sqrt(p.x * p.x + p.y * p.y) <= s.semiAperture;
}

std::vector<PathStep> ghostPath(int surfaceCount, int first, int second) {
    std::vector<PathStep> path;
    if (first < 0) {
        for (int k = 0; k < surfaceCount; ++k) path.push_back({k, false});
        return path;
    }
    for (int k = 0; k < first; ++k) path.push_back({k, false});
    path.push_back({first, true});
    for (int k = first - 1; k > second; --k) path.push_back({k, false});
    path.push_back({second, true});
    for (int k = second + 1; k < surfaceCount; ++k) path.push_back({k, false});
    return path;
}

bool canReflect(const TraceLens& lens, int surface) {
    const TraceSurface& s = lens.surfaces[std::size_t(surface)];
    return !s.stop && (s.nAfter != lens.nBefore(std::size_t(surface)) || s.coating.present());
}

Iris makeIris(const LensAperture& a) {
    Iris iris;
    iris.roundness = a.roundness;
    if (a.blades < 3 || a.roundness >= 1.0) return iris;
    iris.blades = std::min(a.blades, 32);
    const double sector = 2.0 * M_PI / iris.blades;
    iris.cosHalf = std::cos(sector / 2.0);
    // The bowed blade r(phi) = (1 - rho) P(phi) + rho, P the straight blade's polar radius, is
    // convex where r^2 + 2 r'^2 - r r'' >= 0; P itself gives 0 (a line), so this reduces to
    // (1 - rho) (1 - 2 tan^2(pi / n)) + rho >= 0 at the vertices, where P'' is largest: every
    // iris of 6 or more blades, a 5-bladed one from rho = 0.053, 4 from 0.5, 3 from 5/6.
    const double t = std::tan(sector / 2.0);
    iris.convex =
        iris.roundness <= 0 || (1 - iris.roundness) * (1 - 2 * t * t) + iris.roundness >= 0;
    // Vertex k sits at rotation + k sector; the edge between vertices k and k+1 faces the
    // half-way angle.
    for (int k = 0; k < iris.blades; ++k) {
        const double angle = a.rotationDeg * M_PI / 180.0 + (k + 0.5) * sector;
        iris.normals[std::size_t(2 * k)] = std::cos(angle);
        iris.normals[std::size_t(2 * k + 1)] = std::sin(angle);
    }
    return iris;
}

double irisRadius(const Iris& iris, double x, double y) {
    const double r = std::sqrt(x * x + y * y);
    if (iris.blades < 3) return r;
    // The inscribed n-gon's own "radius" of the point: its largest edge-normal projection over
    // the edge distance cos(pi / n).
    double d = 0;
    for (int k = 0; k < iris.blades; ++k)
        d = std::max(
            d, x * iris.normals[std::size_t(2 * k)] + y * iris.normals[std::size_t(2 * k + 1)]);
    d /= iris.cosHalf;
    if (iris.roundness <= 0 || r == 0) return d;
    // Roundness rho blends the edge's radius at this angle, P = r / d, toward the circle's 1:
    // q = r / (P + (1 - P) rho), each blade bowed outward.
    return r * d / (r + (d - r) * iris.roundness);
}

double apertureRadius(const LensAperture& a, double x, double y) {
    return irisRadius(makeIris(a), x, y);
}

Vec beamDirection(double angleXDeg, double angleYDeg) {
    Vec d{std::tan(angleXDeg * M_PI / 180.0), std::tan(angleYDeg * M_PI / 180.0), 1.0};
    return d * (1.0 / std::sqrt(dot(d, d)));
}

Vec beamOrigin(const TraceLens& lens, Vec dir, double x, double y) {
    // Start a little in front of the first surface's deepest point, on the ray through (x, y, 0).
    const TraceSurface& s = lens.surfaces.front();
    const double depth = std::fabs(s.radius) > 0 ? std::fabs(s.radius) : s.semiAperture;
    const double zStart = -(std::min(depth, 4.0 * s.semiAperture) + 1.0);
    return Vec{x, y, 0.0} + dir * (zStart / dir.z);
}

int beamMargin(const TraceLens& lens, Vec dir, double spacing) {
    const TraceSurface& s = lens.surfaces.front();
    const double sag = std::fabs(surfaceSag(s.radius, s.semiAperture));
    const double reach = sag * std::max(std::fabs(dir.x), std::fabs(dir.y)) / dir.z;
    return int(std::ceil(reach / spacing));
}

Vec Beam::origin(const TraceLens& lens, int cell, double fx, double fy) const {
    const int ix = cell % cellsPerSide - margin, iy = cell / cellsPerSide - margin;
    return beamOrigin(lens, dir, -semiAperture + (ix + fx) * spacing,
                      -semiAperture + (iy + fy) * spacing);
}

Beam makeBeam(const TraceLens& lens, Vec dir, int gridSide) {
    Beam b;
    b.dir = dir;
    b.semiAperture = lens.surfaces.front().semiAperture;
    b.spacing = 2.0 * b.semiAperture / gridSide;
    b.margin = beamMargin(lens, dir, b.spacing);
    b.cellsPerSide = gridSide + 2 * b.margin;
    for (int cell = 0; cell < b.cellsPerSide * b.cellsPerSide; ++cell) {
        SplitMix64 random{std::uint64_t(cell)};
        const double fx = random.nextDouble(), fy = random.nextDouble();
        const Vec o = b.origin(lens, cell, fx, fy);
        if (entersLens(lens, o, dir)) b.origins.push_back(o), b.cells.push_back(cell);
    }
    return b;
}

RayResult traceRay(const TraceLens& lens, const std::vector<PathStep>& path, Vec o, Vec d,
                   bool clip, std::vector<Vec>* points) {
    RayResult r;
    double n = 1.0, throughput = 1.0;
    // The leg, not the sign of d.z, says which side of a surface the ray comes from: between the
    // two reflections every surface is crossed from the back, even by a steep ray in a curved
    // air gap that moves toward +z there.
    bool forwardLeg = true;
    if (points) points->push_back(o);
    for (const PathStep& step : path) {
        const TraceSurface& s = lens.surfaces[std::size_t(step.surface)];
        const double t = intersect(s, o, d);
        if (t < 0) return r;
        o = o + d * t;
        if (points) points->push_back(o);
        // sqrt, not std::hypot: heights are millimetres (no overflow to guard against), and
        // glibc's hypot was 44% of a ghost analysis.
        const double radial = std::sqrt(o.x * o.x + o.y * o.y) / s.semiAperture;
        if (s.stop) {
            const double q = irisRadius(lens.iris, o.x / s.semiAperture, o.y / s.semiAperture);
            if (clip && q > 1.0) return r;
            if (r.stopCrossings < kMaxStopCrossings) {
                r.stop[std::size_t(2 * r.stopCrossings)] = o.x / s.semiAperture;
                r.stop[std::size_t(2 * r.stopCrossings + 1)] = o.y / s.semiAperture;
                ++r.stopCrossings;
            }
        } else {
            if (clip && radial > 1.0) return r;
            r.vignette = std::max(r.vignette, radial);
        }
        // The normal facing the incoming ray.
        Vec normal = s.radius == 0.0
                         ? Vec{0, 0, 1}
                         : Vec{o.x / s.radius, o.y / s.radius, (o.z - (s.z + s.radius)) / s.radius};
        if (dot(normal, d) > 0) normal = normal * -1.0;
        const double cosi = std::min(1.0, -dot(normal, d));
        const double other = forwardLeg ? s.nAfter : lens.nBefore(std::size_t(step.surface));
        const std::vector<float>& table = forwardLeg ? s.reflectFromFront : s.reflectFromBack;
        const double at = cosi * kReflectanceSteps;
        const int k = std::min(int(at), kReflectanceSteps - 1);
        const double reflectance =
            table[std::size_t(k)] + (table[std::size_t(k) + 1] - table[std::size_t(k)]) * (at - k);
        if (step.reflect) {
            throughput *= reflectance;
            d = d + normal * (2.0 * cosi);
            forwardLeg = !forwardLeg;
        } else {
            throughput *= 1.0 - reflectance;
            const double eta = n / other;
            const double cost2 = 1.0 - eta * eta * (1.0 - cosi * cosi);
            if (cost2 < 0) return r;  // total internal reflection: not this path's light
            d = d * eta + normal * (eta * cosi - std::sqrt(cost2));
            n = other;
        }
    }
    if (d.z <= 0) return r;
    const double t = (lens.sensorZ - o.z) / d.z;
    if (t < 0) return r;
    o = o + d * t;
    if (points) points->push_back(o);
    r.alive = true;
    r.x = o.x, r.y = o.y;
    r.throughput = throughput;
    return r;
}

}  // namespace flarekit::lens
