// The CPU post-process chain: one function wiring the passes (style.md habit 4). Each pass is
// a per-pixel kernel from its folder run over an image by runPass; GpuChain.cpp is the same
// wiring with GL draws.
#include "flarekit/PostFx.h"
#include "postfx/ChainPlan.h"
#include "postfx/dirt/LensDirtCache.h"

namespace flarekit {

using namespace postfx;

namespace {

//! `image` at size s, reallocated only when the size changes; contents are left to the pass.
Image& ensure(Image& image, Size s) {
    if (image.width() != s.width || image.height() != s.height) image = Image(s.width, s.height);
    return image;
}

}  // namespace

struct CpuPostFx::Impl {
    std::vector<Image> mips, ups;
    Image ghosts, halo, streaks, right, ping, lens;
    LensDirtCache dirt;
};

CpuPostFx::CpuPostFx() : m(std::make_unique<Impl>()) {}
CpuPostFx::~CpuPostFx() = default;
CpuPostFx::CpuPostFx(CpuPostFx&&) noexcept = default;
CpuPostFx& CpuPostFx::operator=(CpuPostFx&&) noexcept = default;

Status CpuPostFx::run(const Image& input, const PostFxParams& params, PostFxResult& result, const PostFxOptions& options) {
    auto planned = planChain(input.width(), input.height(), params);
    if (!planned) return planned.error();
    const ChainPlan& plan = *planned;
    Impl& b = *m;
    PassClock clock(options.times);
    const Size work = plan.work();
    b.mips.resize(plan.levels.size()), b.ups.resize(plan.levels.size());
    for (std::size_t i = 0; i < plan.levels.size(); ++i) ensure(b.mips[i], plan.levels[i]);

    // 1. Bright pass at 1/2, then the 13-tap downsample chain.
    clock.run("bright", plan.levels[0], [&] {
        runPass(b.mips[0], [&, in = Tex(input)](int x, int y) { return brightPixel(plan.bright, in, x, y); });
    });
    clock.run("downsample", plan.levels[1], [&] {
        for (std::size_t i = 0; i < plan.down.size(); ++i) {
            runPass(b.mips[i + 1], [&, src = Tex(b.mips[i])](int x, int y) { return downsamplePixel(plan.down[i], src, x, y); });
        }
    });

    // 2. Blur: the progressive tent upsample back to 1/4, the bloom buffer (the coarsest
    //    level is its own U).
    const auto up = [&](std::size_t level) -> const Image& { return level + 1 == plan.levels.size() ? b.mips[level] : b.ups[level]; };
    clock.run("upsample", work, [&] {
        for (std::size_t i = plan.up.size(); i-- > 0;) {
            runPass(ensure(b.ups[i + 1], plan.levels[i + 1]), [&, fine = Tex(b.mips[i + 1]), coarse = Tex(up(i + 2))](int x, int y) {
                return upsamplePixel(plan.up[i], fine, coarse, x, y);
            });
        }
    });
    const Image& bloom = up(kWorkLevel);

    // 3. Ghosts and halo from the bloom buffer; 4. streaks from the 1/4 bright image.
    // A pass that is off leaves its buffer black for the lens pass.
    for (auto [image, on] : {std::pair{&b.ghosts, plan.ghostsOn()}, std::pair{&b.halo, plan.haloOn()}, std::pair{&b.streaks, plan.streaksOn()}}) {
        ensure(*image, work);
        if (!on) image->fill({});
    }
    if (plan.ghostsOn()) {
        clock.run("ghosts", work, [&] {
            runPass(b.ghosts, [&, src = Tex(bloom)](int x, int y) { return ghostsPixel(plan.ghosts, src, x, y); });
        });
    }
    if (plan.haloOn()) {
        clock.run("halo", work, [&] { runPass(b.halo, [&, src = Tex(bloom)](int x, int y) { return haloPixel(plan.halo, src, x, y); }); });
    }
    if (plan.streaksOn()) {
        clock.run("streaks", work, [&] {
            // The right chain ends in `right`, the left one in `streaks`; `ping` is the other buffer of each.
            ensure(b.ping, work), ensure(b.right, work);
            const auto chain = [&](const std::vector<StreakUniforms>& passes, Image& last) {
                const Image* src = &b.mips[kWorkLevel];
                for (std::size_t i = 0; i < passes.size(); ++i) {
                    Image& dst = (passes.size() - i) % 2 == 1 ? last : b.ping;
                    runPass(dst, [&, t = Tex(*src), o = Tex(b.right)](int x, int y) { return streakPixel(passes[i], t, o, x, y); });
                    src = &dst;
                }
            };
            chain(plan.streaks.right, b.right);
            chain(plan.streaks.left, b.streaks);
        });
    }

    // 5. The lens buffer (chromatic aberration, starburst, dirt) and the full-res composite.
    if (plan.dirtOn()) b.dirt.update(work.width, work.height, plan.dirt);  // read only when on
    clock.run("lens", work, [&] {
        const LensInputs in{Tex(bloom), Tex(b.ghosts), Tex(b.halo), Tex(b.streaks), Tex(b.dirt.image())};
        runPass(ensure(b.lens, work), [&](int x, int y) { return lensPixel(plan.lens, in, x, y); });
    });
    clock.run("composite", plan.input, [&] {
        runPass(ensure(result.final, plan.input),
                [&, in = Tex(input), l = Tex(b.lens)](int x, int y) { return compositePixel(plan.composite, in, l, x, y); });
    });

    if (options.keepLayers) {
        result.bloom = bloom;
        scaleInPlace(result.bloom, params.bloom.intensity);
        result.ghosts = b.ghosts, result.halo = b.halo, result.streaks = b.streaks, result.lens = b.lens;
    }
    return Ok{};
}

Result<PostFxResult> postFxCpu(const Image& input, const PostFxParams& params, const PostFxOptions& options) {
    PostFxResult result;
    CpuPostFx chain;
    if (Status s = chain.run(input, params, result, options); !s) return s.error();
    return result;
}

Image resizeBilinear(const Image& image, int width, int height) {
    Image out(std::max(1, width), std::max(1, height));
    if (image.empty()) return out;
    const Vec2 inv = inverseSize(out.width(), out.height());
    runPass(out, [&, src = Tex(image)](int x, int y) { return bilinear(src, pixelUv(x, y, inv)); });
    return out;
}

}  // namespace flarekit
