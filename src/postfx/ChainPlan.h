// The chain's sizes and every pass's uniforms, computed once from the params and the input
// size, and shared by the CPU chain (Chain.cpp) and the GL chain (GpuChain.cpp): the two differ
// only in who runs the kernels.
#pragma once

#include <string>
#include <vector>

#include "flarekit/PostFx.h"
#include "postfx/blur/Upsample.h"
#include "postfx/brightpass/BrightPass.h"
#include "postfx/composite/Composite.h"
#include "postfx/composite/Lens.h"
#include "postfx/downsample/Downsample.h"
#include "postfx/ghosts/Ghosts.h"
#include "postfx/halo/Halo.h"
#include "postfx/streaks/Streaks.h"

namespace flarekit::postfx {

struct Size {
    int width = 0, height = 0;
    double megapixels() const { return double(width) * double(height) * 1e-6; }
};

//! Index of the working resolution in ChainPlan::levels: level 1 is 1/4 of the input.
inline constexpr std::size_t kWorkLevel = 1;

struct ChainPlan {
    Size input;
    std::vector<Size> levels;  //!< levels[0] = 1/2 (bright pass) ... levels.back() the coarsest
    BrightUniforms bright;
    std::vector<DownsampleUniforms> down;  //!< down[i] writes levels[i + 1] from levels[i]
    std::vector<UpsampleUniforms> up;      //!< up[i] writes levels[i + 1] from levels[i + 2]; empty when levels.size() == 2
    GhostsUniforms ghosts;
    HaloUniforms halo;
    StreakPlan streaks;
    LensUniforms lens;
    CompositeUniforms composite;
    DirtParams dirt;

    Size work() const { return levels[kWorkLevel]; }
    bool haloOn() const { return halo.intensity > 0.f; }
    bool ghostsOn() const { return !ghosts.ghosts.empty() && ghosts.intensity > 0.f; }
    bool dirtOn() const { return lens.dirtIntensity > 0.f; }
    bool streaksOn() const { return !streaks.left.empty(); }
};

//! Multiplies every value (the bloom layer is the bloom buffer x bloom.intensity).
inline void scaleInPlace(Image& image, float k) {
    for (std::size_t i = 0; i < image.pixelCount() * 4; ++i) image.data()[i] *= k;
}

//! Checks what JSON validation would (for params built in code) and plans the chain.
Result<ChainPlan> planChain(int width, int height, const PostFxParams& params);

//! Times each pass when asked (CPU: wall clock).
class PassClock {
public:
    explicit PassClock(std::vector<PassTime>* times) : m_times(times) {}
    template <typename Work>
    void run(const char* pass, Size written, const Work& work);
    //! Adds a measurement (the GL chain times its passes itself).
    void add(const char* pass, Size written, double ms, double wallMs);

private:
    std::vector<PassTime>* m_times;
};

}  // namespace flarekit::postfx

#include <chrono>

template <typename Work>
void flarekit::postfx::PassClock::run(const char* pass, Size written, const Work& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    if (!m_times) return;
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    add(pass, written, ms, ms);
}

inline void flarekit::postfx::PassClock::add(const char* pass, Size written, double ms, double wallMs) {
    if (!m_times) return;
    for (PassTime& t : *m_times) {
        if (t.pass == pass) {
            t.milliseconds += ms, t.wallMilliseconds += wallMs, t.megapixels += written.megapixels();
            return;
        }
    }
    m_times->push_back({pass, ms, wallMs, written.megapixels()});
}
