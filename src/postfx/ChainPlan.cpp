#include "postfx/ChainPlan.h"

#include <cmath>

namespace flarekit::postfx {

namespace {
bool finite(float x) { return std::isfinite(x); }

Status checkParams(const PostFxParams& p) {
    if (p.ghosts.size() > std::size_t(kMaxGhosts)) return invalidInput("postfx: at most 32 ghosts, got " + std::to_string(p.ghosts.size()));
    for (const GhostParams& g : p.ghosts) {
        if (g.samples < 1 || g.samples > 64) return invalidInput("postfx: ghost samples: expected 1..64, got " + std::to_string(g.samples));
        if (!finite(g.scale) || std::abs(g.scale) < 0.05f || !finite(g.blur) || !finite(g.threshold) || !finite(g.falloff)) {
            return invalidInput("postfx: ghost: expected finite values and |scale| >= 0.05");
        }
    }
    if (p.bloom.levels < 2 || p.bloom.levels > 12) return invalidInput("postfx: bloom.levels: expected 2..12, got " + std::to_string(p.bloom.levels));
    if (p.starburst.spokes < 2 || p.starburst.spokes > kMaxSpokes) return invalidInput("postfx: starburst.spokes: expected 2..64");
    if (!(p.starburst.width > 0.f)) return invalidInput("postfx: starburst.width: expected > 0");
    for (float x : {p.bright.threshold, p.bright.knee, p.bloom.intensity, p.bloom.spread, p.halo.intensity, p.halo.radius,
                    p.halo.thickness, p.streaks.intensity, p.streaks.length, p.chromatic.amount, p.dirt.intensity,
                    p.tone.exposure, p.flareIntensity}) {
        if (!finite(x) || x < 0.f) return invalidInput("postfx: parameters must be finite and non-negative");
    }
    return Ok{};
}
}  // namespace

Result<ChainPlan> planChain(int width, int height, const PostFxParams& p) {
    if (width < 1 || height < 1) return invalidInput("postfx: empty image");
    if (Status s = checkParams(p); !s) return s.error();
    ChainPlan plan;
    plan.input = {width, height};
    Size s{halfSize(width), halfSize(height)};
    for (int i = 0; i < p.bloom.levels; ++i) {
        plan.levels.push_back(s);
        s = {halfSize(s.width), halfSize(s.height)};
    }
    plan.bright = {p.bright.threshold, p.bright.knee, inverseSize(plan.levels[0].width, plan.levels[0].height)};
    for (std::size_t i = 0; i + 1 < plan.levels.size(); ++i) {
        const Size src = plan.levels[i], dst = plan.levels[i + 1];
        plan.down.push_back({inverseSize(dst.width, dst.height), inverseSize(src.width, src.height)});
    }
    // U(k) = (D(k) + spread U(k+1)) x scale, from the coarsest up to the working level; the last
    // step divides by 1 + spread + spread^2 + ... so a flat field stays flat.
    double norm = 0, weight = 1;
    for (std::size_t i = kWorkLevel; i < plan.levels.size(); ++i, weight *= p.bloom.spread) norm += weight;
    for (std::size_t i = 0; i + 2 < plan.levels.size(); ++i) {
        const Size dst = plan.levels[i + 1], coarse = plan.levels[i + 2];
        plan.up.push_back({inverseSize(dst.width, dst.height), inverseSize(coarse.width, coarse.height), p.bloom.spread,
                           i == 0 ? float(1.0 / norm) : 1.f});
    }
    const Size work = plan.work();
    const Vec2 invWork = inverseSize(work.width, work.height);
    const float aspect = float(width) / float(height);
    plan.ghosts = {invWork, invWork, p.ghosts, p.flareIntensity};
    plan.halo = {invWork, aspect, p.halo, p.flareIntensity * p.halo.intensity};
    if (p.streaks.intensity > 0.f && p.flareIntensity > 0.f) {
        plan.streaks = streakPasses(p.streaks, work.width, p.flareIntensity * p.streaks.intensity);
    }
    plan.lens = {invWork, aspect, p.bloom.intensity, p.chromatic.amount, p.dirt.intensity, starburstUniforms(p.starburst)};
    plan.composite = {inverseSize(width, height), int(p.tone.op), p.tone.exposure};
    plan.dirt = p.dirt;
    return plan;
}

}  // namespace flarekit::postfx
