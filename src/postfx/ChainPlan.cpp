#include "postfx/ChainPlan.h"

#include <cmath>

namespace flarekit::postfx {


Result<ChainPlan> planChain(int width, int height, const PostFxParams& p) {
    if (width < 1 || height < 1) return invalidInput("postfx: empty image");
    if (Status s = validatePostFxParams(p); !s) return invalidInput("postfx: " + s.error().message);
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
