// SPDX-License-Identifier: Apache-2.0
// The CPU executor of the post-process chain: every step of the plan is its pass's pixel
// kernel run over the output image in parallel (runPass). The wiring is ChainPlan.cpp's
// wireChain; GpuChain.cpp executes the same steps with GL draws.
#include <array>

#include "flarekit/PostFx.h"
#include "postfx/ChainPlan.h"
#include "postfx/PassClock.h"
#include "postfx/dirt/LensDirtCache.h"

namespace flarekit {

using namespace postfx;

namespace {

//! `image` at size s, reallocated only when the size changes (a new Image is zero-filled);
//! contents are left to the pass. True when it was made new.
bool ensure(Image& image, Size s) {
    if (image.width() == s.width && image.height() == s.height) return false;
    image = Image(s.width, s.height);
    return true;
}

}  // namespace

struct CpuPostFx::Impl {
    ChainBuffers<Image> buffers;
    LensDirtCache dirt;
    const Image* input = nullptr;
    Image* final = nullptr;

    const Image& read(BufferId id) {
        if (id.kind == BufferKind::Input) return *input;
        if (id.kind == BufferKind::Dirt) return dirt.image();
        return write(id);
    }
    //! A buffer a step writes (never the input or the dirt texture).
    Image& write(BufferId id) { return id.kind == BufferKind::Final ? *final : *buffers.find(id); }

    //! Runs the chain on `input` into `finalImage` (which may be the input itself).
    Status run(const Image& source, Image& finalImage, const PostFxParams& params,
               PostFxResult& result, const PostFxOptions& options);

    //! One step: its pass's kernel over every output pixel, reading its inputs as textures.
    void execute(const ChainPlan& plan, const Step& step) {
        Image& out = write(step.output);
        const bool fresh = ensure(out, plan.sizeOf(step.output));
        // The inputs by value in the kernel's closure (as the uniforms are its own copy): the
        // compiler then knows the output rows cannot alias them and keeps them in registers.
        std::array<Tex, kMaxStepInputs> in{};
        for (std::size_t i = 0; i < step.inputs.size(); ++i) in[i] = Tex(read(step.inputs[i]));
        std::visit(
            [&, in](const auto& stepUniforms) {
                using U = std::decay_t<decltype(stepUniforms)>;
                if constexpr (std::is_same_v<U, ClearStep>) {
                    if (!fresh) out.fill({});  // a new buffer is already transparent black
                } else if constexpr (requires { drawPass(stepUniforms, in.data(), out); }) {
                    drawPass(stepUniforms, in.data(), out);  // a pass that draws rows itself
                } else {
                    runPass(out, [u = stepUniforms, in](int x, int y) {
                        return passPixel(u, in.data(), x, y);
                    });
                }
            },
            step.uniforms);
    }
};

CpuPostFx::CpuPostFx() : m(std::make_unique<Impl>()) {}
CpuPostFx::~CpuPostFx() = default;
CpuPostFx::CpuPostFx(CpuPostFx&&) noexcept = default;
CpuPostFx& CpuPostFx::operator=(CpuPostFx&&) noexcept = default;

Status CpuPostFx::run(const Image& input, const PostFxParams& params, PostFxResult& result,
                      const PostFxOptions& options) {
    return m->run(input, result.final, params, result, options);
}

Status CpuPostFx::runInPlace(Image& image, const PostFxParams& params, PostFxResult& result,
                             const PostFxOptions& options) {
    return m->run(image, image, params, result, options);
}

Status CpuPostFx::Impl::run(const Image& source, Image& finalImage, const PostFxParams& params,
                            PostFxResult& result, const PostFxOptions& options) {
    auto planned = planChain(source.width(), source.height(), fitToFrame(params, source));
    if (!planned) return planned.error();
    // The composite is the chain's last step (wireChain), the only one writing Final.
    if (!options.composite && planned->steps.back().output.kind == BufferKind::Final)
        planned->steps.pop_back();
    const ChainPlan& plan = *planned;
    input = &source, final = &finalImage;
    buffers.mips.resize(plan.levels.size()), buffers.ups.resize(plan.levels.size());
    if (plan.dirtOn)
        dirt.update(plan.work().width, plan.work().height, plan.dirt);  // read only when on
    PassClock clock(options.times);
    forEachGroup(
        plan, [&](const char* label, Size written, std::size_t first, std::size_t last, bool off) {
            const auto group = [&] {
                for (std::size_t i = first; i < last; ++i) execute(plan, plan.steps[i]);
            };
            off ? group() : clock.run(label, written, group);
        });
    if (options.keepLayers) {
        result.bloom = read(plan.bloom);
        result.bloom.scale(params.bloom.intensity);
        const ChainBuffers<Image>& l = buffers;
        result.ghosts = l.ghosts, result.halo = l.halo, result.streaks = l.streaks,
        result.lens = l.lens;
    }
    return Ok{};
}

Result<PostFxResult> postFxCpu(const Image& input, const PostFxParams& params,
                               const PostFxOptions& options) {
    PostFxResult result;
    CpuPostFx chain;
    if (Status s = chain.run(input, params, result, options); !s) return s.error();
    return result;
}

Image resizeBilinear(const Image& image, int width, int height) {
    if (image.empty()) return Image(std::max(1, width), std::max(1, height));
    Image out(std::max(1, width), std::max(1, height), Image::Uncleared{});
    // bilinear(image, pixelUv(x, y)) at every pixel, filtered separably: an upsample by 4
    // filters each source row across once for the four output rows it feeds, instead of four
    // taps per output pixel.
    const BilinearColumns columns(Tex(image), out.width(), inverseSize(out.width(), out.height()));
    runUpsamplePass(out, columns, [](int, int, F4 up) { return up; });
    return out;
}

}  // namespace flarekit
