// SPDX-License-Identifier: Apache-2.0
#include <chrono>

#include "flarekit/gl/HeadlessGl.h"
#include "flarekit/gl/PostFxBackend.h"

namespace flarekit::gl {

namespace {
class GlBackend final : public PostFxBackend {
  public:
    explicit GlBackend(GlTransfer transfer) : m_transfer(transfer) {}
    std::string name() const override { return "gl"; }
    bool usesGl() const override { return true; }

    Result<PostFxResult> run(Image& image, bool, const PostFxParams& params,
                             const PostFxOptions& options, int repeat, double& warmSeconds,
                             const std::string& in, const JobEvents& events) const override {
        auto context = createQuietHeadlessGl();
        if (!context) return context.error();
        if (Status s = checkGlFrame(image.width(), image.height(), 1, in + ": image"); !s)
            return s.error();
        auto chain = GpuPostFx::create();
        if (!chain) return chain.error();
        const std::string renderer = (*context)->renderer();
        if (options.times) events.say("OpenGL: " + renderer);
        const bool software = (*context)->software();
        PostFxOptions glOptions = options;
        if (m_transfer == GlTransfer::Float || (m_transfer == GlTransfer::Auto && software))
            glOptions.halfInput = glOptions.halfReadback = false;
        PostFxResult result;
        warmSeconds = 0;
        for (int i = 0; i < repeat; ++i) {
            const auto start = std::chrono::steady_clock::now();
            auto r = chain->run(image, params, glOptions);  // upload, passes, read-back
            if (!r) return r.error();
            result = std::move(*r);
            if (i > 0)
                warmSeconds +=
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        if (repeat > 1) warmSeconds /= repeat - 1;
        return result;
    }

  private:
    GlTransfer m_transfer;
};
}  // namespace

std::shared_ptr<const PostFxBackend> glPostFxBackend(GlTransfer transfer) {
    return std::make_shared<const GlBackend>(transfer);
}

}  // namespace flarekit::gl
