// The CPU post-process chain: one function wiring the passes (style.md habit 4). Each pass is
// a per-pixel kernel from its folder run over an image by runPass; GpuChain.cpp is the same
// wiring with GL draws.
#include "flarekit/PostFx.h"
#include "postfx/ChainPlan.h"

namespace flarekit {

using namespace postfx;

namespace {

Image sized(Size s) { return Image(s.width, s.height); }

Image scaled(const Image& image, float k) {
    Image out = image;
    for (std::size_t i = 0; i < out.pixelCount() * 4; ++i) out.data()[i] *= k;
    return out;
}

}  // namespace

Result<PostFxResult> postFxCpu(const Image& input, const PostFxParams& params, const PostFxOptions& options) {
    auto planned = planChain(input.width(), input.height(), params);
    if (!planned) return planned.error();
    const ChainPlan& plan = *planned;
    PassClock clock(options.times);
    const Size work = plan.work();

    // 1. Bright pass at 1/2, then the 13-tap downsample chain.
    std::vector<Image> mips;
    for (const Size& s : plan.levels) mips.push_back(sized(s));
    clock.run("bright", plan.levels[0], [&] {
        runPass(mips[0], [&, in = Tex(input)](int x, int y) { return brightPixel(plan.bright, in, x, y); });
    });
    clock.run("downsample", plan.levels[1], [&] {
        for (std::size_t i = 0; i < plan.down.size(); ++i) {
            runPass(mips[i + 1], [&, src = Tex(mips[i])](int x, int y) { return downsamplePixel(plan.down[i], src, x, y); });
        }
    });

    // 2. Blur: the progressive tent upsample back to 1/4, the bloom buffer.
    std::vector<Image> ups(mips.size());
    ups.back() = mips.back();
    clock.run("upsample", work, [&] {
        for (std::size_t i = plan.up.size(); i-- > 0;) {
            ups[i + 1] = sized(plan.levels[i + 1]);
            runPass(ups[i + 1], [&, fine = Tex(mips[i + 1]), coarse = Tex(ups[i + 2])](int x, int y) {
                return upsamplePixel(plan.up[i], fine, coarse, x, y);
            });
        }
    });
    const Image& bloom = ups[kWorkLevel];

    // 3. Ghosts and halo from the bloom buffer; 4. streaks from the 1/4 bright image.
    Image ghosts = sized(work), halo = sized(work), streaks = sized(work);
    if (plan.ghostsOn()) {
        clock.run("ghosts", work, [&] {
            runPass(ghosts, [&, src = Tex(bloom)](int x, int y) { return ghostsPixel(plan.ghosts, src, x, y); });
        });
    }
    if (plan.haloOn()) {
        clock.run("halo", work, [&] { runPass(halo, [&, src = Tex(bloom)](int x, int y) { return haloPixel(plan.halo, src, x, y); }); });
    }
    if (plan.streaksOn()) {
        clock.run("streaks", work, [&] {
            // Right chain ends in `right`, left chain in `streaks`; `ping` is the other buffer of each.
            Image ping = sized(work), right = sized(work);
            const auto chain = [&](const std::vector<StreakUniforms>& passes, Image& last) {
                const Image* src = &mips[kWorkLevel];
                for (std::size_t i = 0; i < passes.size(); ++i) {
                    Image& dst = (passes.size() - i) % 2 == 1 ? last : ping;
                    runPass(dst, [&, t = Tex(*src), o = Tex(right)](int x, int y) { return streakPixel(passes[i], t, o, x, y); });
                    src = &dst;
                }
            };
            chain(plan.streaks.right, right);
            chain(plan.streaks.left, streaks);
        });
    }

    // 5. The lens buffer (chromatic aberration, starburst, dirt) and the full-res composite.
    const Image dirt = plan.dirtOn() ? makeLensDirt(work.width, work.height, plan.dirt) : sized({1, 1});
    Image lens = sized(work);
    clock.run("lens", work, [&] {
        const LensInputs in{Tex(bloom), Tex(ghosts), Tex(halo), Tex(streaks), Tex(dirt)};
        runPass(lens, [&](int x, int y) { return lensPixel(plan.lens, in, x, y); });
    });
    PostFxResult result;
    result.final = sized(plan.input);
    clock.run("composite", plan.input, [&] {
        runPass(result.final, [&, in = Tex(input), l = Tex(lens)](int x, int y) { return compositePixel(plan.composite, in, l, x, y); });
    });

    if (options.keepLayers) {
        result.bloom = scaled(bloom, params.bloom.intensity);
        result.ghosts = std::move(ghosts), result.halo = std::move(halo), result.streaks = std::move(streaks);
        result.lens = std::move(lens);
    }
    return result;
}

}  // namespace flarekit

namespace flarekit {

Image resizeBilinear(const Image& image, int width, int height) {
    Image out(std::max(1, width), std::max(1, height));
    if (image.empty()) return out;
    const Vec2 inv = inverseSize(out.width(), out.height());
    runPass(out, [&, src = Tex(image)](int x, int y) { return bilinear(src, pixelUv(x, y, inv)); });
    return out;
}

}  // namespace flarekit
