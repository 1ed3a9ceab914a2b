// SPDX-License-Identifier: Apache-2.0
#include "postfx/ChainPlan.h"

#include <cmath>

namespace flarekit::postfx {

namespace {

BufferId mip(std::size_t level) {
    return {BufferKind::Mip, level};
}
BufferId named(BufferKind kind) {
    return {kind, 0};
}

//! The upsample result at `level`: the coarsest level is its own (nothing coarser to add).
BufferId upAt(const ChainPlan& plan, std::size_t level) {
    return level + 1 == plan.levels.size() ? mip(level) : BufferId{BufferKind::Up, level};
}

void add(ChainPlan& plan, const char* label, PassUniforms u, std::vector<BufferId> in,
         BufferId out) {
    plan.steps.push_back({label, std::move(u), std::move(in), out});
}

//! 1. Bright pass at 1/2, the 13-tap downsample chain, and the tent upsample back to the
//! working level: U(k) = (D(k) + spread U(k+1)) x scale, from the coarsest up; the last step
//! divides by 1 + spread + spread^2 + ... so a flat field stays flat.
void addBloom(ChainPlan& plan, const PostFxParams& p) {
    add(plan, "bright",
        BrightUniforms{p.bright.threshold, p.bright.knee, p.bright.ceiling,
                       inverseSize(plan.levels[0].width, plan.levels[0].height)},
        {named(BufferKind::Input)}, mip(0));
    for (std::size_t i = 0; i + 1 < plan.levels.size(); ++i) {
        const Size src = plan.levels[i], dst = plan.levels[i + 1];
        add(plan, "downsample",
            DownsampleUniforms{inverseSize(dst.width, dst.height),
                               inverseSize(src.width, src.height)},
            {mip(i)}, mip(i + 1));
    }
    double norm = 0, weight = 1;
    for (std::size_t i = kWorkLevel; i < plan.levels.size(); ++i, weight *= p.bloom.spread)
        norm += weight;
    for (std::size_t i = plan.levels.size() - 2; i-- > 0;) {
        const Size dst = plan.levels[i + 1], coarse = plan.levels[i + 2];
        add(plan, "upsample",
            UpsampleUniforms{inverseSize(dst.width, dst.height),
                             inverseSize(coarse.width, coarse.height), p.bloom.spread,
                             i == 0 ? float(1.0 / norm) : 1.f},
            {mip(i + 1), upAt(plan, i + 2)}, BufferId{BufferKind::Up, i + 1});
    }
    plan.bloom = upAt(plan, kWorkLevel);
}

//! 2. Ghosts and halo from the bloom buffer; a pass that is off clears its buffer instead.
void addGhostsAndHalo(ChainPlan& plan, const PostFxParams& p) {
    const Size work = plan.work();
    const Vec2 invWork = inverseSize(work.width, work.height);
    GhostsUniforms ghosts = ghostsUniforms(invWork, invWork, p.ghosts, p.flareIntensity);
    const bool ghostsOn = !ghosts.ghosts.empty() && ghosts.intensity > 0.f;
    add(plan, "ghosts", ghostsOn ? PassUniforms(std::move(ghosts)) : PassUniforms(ClearStep{}),
        {plan.bloom}, named(BufferKind::Ghosts));
    const float aspect = float(plan.input.width) / float(plan.input.height);
    const HaloUniforms halo{invWork, aspect, p.halo, p.flareIntensity * p.halo.intensity};
    add(plan, "halo", halo.intensity > 0.f ? PassUniforms(halo) : PassUniforms(ClearStep{}),
        {plan.bloom}, named(BufferKind::Halo));
}

//! 3. Streaks from the 1/4 bright image: the right chain ends in Right, the left one in Streaks
//! (its last pass adds Right); Ping is the other buffer of each.
void addStreaks(ChainPlan& plan, const PostFxParams& p) {
    StreakPlan streaks;
    if (p.streaks.intensity > 0.f && p.flareIntensity > 0.f) {
        streaks =
            streakPasses(p.streaks, plan.work().width, p.flareIntensity * p.streaks.intensity);
    }
    if (streaks.left.empty())
        return add(plan, "streaks", ClearStep{}, {}, named(BufferKind::Streaks));
    for (auto [passes, last] : {std::pair{&streaks.right, BufferKind::Right},
                                std::pair{&streaks.left, BufferKind::Streaks}}) {
        BufferId src = mip(kWorkLevel);
        for (std::size_t i = 0; i < passes->size(); ++i) {
            const StreakUniforms& u = (*passes)[i];
            const BufferId dst = named((passes->size() - i) % 2 == 1 ? last : BufferKind::Ping);
            std::vector<BufferId> in{src};
            if (u.addOther) in.push_back(named(BufferKind::Right));
            add(plan, "streaks", u, std::move(in), dst);
            src = dst;
        }
    }
}

//! 4. The lens buffer (chromatic aberration, starburst, dirt) and the full-resolution composite.
void addLensAndComposite(ChainPlan& plan, const PostFxParams& p) {
    const Size work = plan.work();
    const float aspect = float(plan.input.width) / float(plan.input.height);
    add(plan, "lens",
        LensUniforms{inverseSize(work.width, work.height), aspect, p.bloom.intensity,
                     p.chromatic.amount, p.dirt.intensity, starburstUniforms(p.starburst)},
        {plan.bloom, named(BufferKind::Ghosts), named(BufferKind::Halo), named(BufferKind::Streaks),
         named(BufferKind::Dirt)},
        named(BufferKind::Lens));
    add(plan, "composite",
        CompositeUniforms{inverseSize(plan.input.width, plan.input.height), int(p.tone.op),
                          p.tone.exposure},
        {named(BufferKind::Input), named(BufferKind::Lens)}, named(BufferKind::Final));
    plan.dirt = p.dirt;
    plan.dirtOn = p.dirt.intensity > 0.f;
}

//! The one wiring of the chain, in the order it runs:
//!   input -> bright (1/2) -> downsample chain -> tent upsample -> bloom (1/4)
//!   bloom -> ghosts, halo;  bright 1/4 -> streaks;  all -> lens (chromatic, starburst, dirt)
//!   input + lens -> composite (+ tone curve)
void wireChain(ChainPlan& plan, const PostFxParams& p) {
    addBloom(plan, p);
    addGhostsAndHalo(plan, p);
    addStreaks(plan, p);
    addLensAndComposite(plan, p);
}

}  // namespace

Size ChainPlan::sizeOf(BufferId id) const {
    switch (id.kind) {
        case BufferKind::Input:
        case BufferKind::Final:
            return input;
        case BufferKind::Mip:
        case BufferKind::Up:
            return levels[id.level];
        default:
            return work();
    }
}

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
    wireChain(plan, p);
    return plan;
}

}  // namespace flarekit::postfx
