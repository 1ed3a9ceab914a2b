// SPDX-License-Identifier: Apache-2.0
// The chain for one input size and one set of params: the buffers' sizes and the list of steps
// (pass, uniforms, inputs, output), computed once and run by either executor, CPU (Chain.cpp)
// or GL (GpuChain.cpp). The two differ only in who runs each step.
#pragma once

#include <string>
#include <vector>

#include "flarekit/PostFx.h"
#include "postfx/PassList.h"

namespace flarekit::postfx {

struct Size {
    int width = 0, height = 0;
    double megapixels() const { return double(width) * double(height) * 1e-6; }
};

//! Index of the working resolution in ChainPlan::levels: level 1 is 1/4 of the input.
inline constexpr std::size_t kWorkLevel = 1;

//! The chain's images. Mip i: the bright image downsampled (levels[i]); Up i: the tent upsample
//! written at level i (the coarsest level is its own); the work-size layers; Dirt: the lens
//! dirt texture, filled by the executor; Input and Final: the caller's images.
enum class BufferKind { Input, Mip, Up, Ghosts, Halo, Streaks, Right, Ping, Lens, Dirt, Final };

struct BufferId {
    BufferKind kind = BufferKind::Input;
    std::size_t level = 0;  //!< Mip and Up only
    bool operator==(const BufferId&) const = default;
};

//! Most inputs a step reads (the lens pass: bloom, ghosts, halo, streaks, dirt).
inline constexpr std::size_t kMaxStepInputs = 5;

//! One step of the chain: `uniforms` says which pass (and with what), reading `inputs` in the
//! order its kernel takes them, writing `output`. Consecutive steps of one `label` are timed
//! together (`postfx -v`).
struct Step {
    const char* label;
    PassUniforms uniforms;
    std::vector<BufferId> inputs;
    BufferId output;
};

//! The buffers an executor owns, of its kind (CPU images, GL targets), looked up by BufferId.
//! Input, Dirt and Final are the executor's own: find() gives nullptr for them.
template <class T>
struct ChainBuffers {
    std::vector<T> mips, ups;
    T ghosts, halo, streaks, right, ping, lens;

    T* find(BufferId id) {
        switch (id.kind) {
            case BufferKind::Mip:
                return &mips[id.level];
            case BufferKind::Up:
                return &ups[id.level];
            case BufferKind::Ghosts:
                return &ghosts;
            case BufferKind::Halo:
                return &halo;
            case BufferKind::Streaks:
                return &streaks;
            case BufferKind::Right:
                return &right;
            case BufferKind::Ping:
                return &ping;
            case BufferKind::Lens:
                return &lens;
            default:
                return nullptr;
        }
    }
    const T* find(BufferId id) const { return const_cast<ChainBuffers*>(this)->find(id); }
};

struct ChainPlan {
    Size input;
    std::vector<Size> levels;  //!< levels[0] = 1/2 (bright pass) ... levels.back() the coarsest
    std::vector<Step> steps;   //!< the chain, in order
    BufferId bloom;            //!< the bloom buffer: the upsample written at the working level
    DirtParams dirt;
    bool dirtOn = false;

    Size work() const { return levels[kWorkLevel]; }
    Size sizeOf(BufferId id) const;
};

//! The steps in timing groups (consecutive steps of one label), in order:
//! f(label, pixels written (the group's largest output), first, last, off) with the group's
//! steps [first, last); `off` is a pass that is off (a clear, not timed).
template <class F>
void forEachGroup(const ChainPlan& plan, F&& f) {
    for (std::size_t first = 0, last = 0; first < plan.steps.size(); first = last) {
        Size written;
        for (last = first;
             last < plan.steps.size() && plan.steps[last].label == plan.steps[first].label;
             ++last) {
            const Size s = plan.sizeOf(plan.steps[last].output);
            if (s.megapixels() > written.megapixels()) written = s;
        }
        f(plan.steps[first].label, written, first, last,
          std::holds_alternative<ClearStep>(plan.steps[first].uniforms));
    }
}

//! Validates the params (validatePostFxParams: JSON and code-built params alike) and plans the
//! chain.
Result<ChainPlan> planChain(int width, int height, const PostFxParams& params);

}  // namespace flarekit::postfx
