// SPDX-License-Identifier: Apache-2.0
#include "flarekit/Tonemap.h"

#include <algorithm>

#include "core/Parallel.h"
#include "core/ToneCurves.h"

namespace flarekit {

void tonemapAcesFitted(Image& image, float exposure) {
    toneMapImage(image, ToneOperator::Aces, exposure);
}

void expandHighlights(Image& image, float gain) {
    parallelFor(0, image.height(), 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* p = image.row(y);
            for (int x = 0; x < image.width(); ++x, p += 4) {
                const float m = std::max({p[0], p[1], p[2]});
                const float s = std::clamp((m - kExpandKnee) / (1.f - kExpandKnee), 0.f, 1.f);
                const float factor = 1.f + (gain - 1.f) * s * s;
                p[0] *= factor, p[1] *= factor, p[2] *= factor;
            }
        }
    });
}

void toneMapImage(Image& image, ToneOperator op, float exposure) {
    if (op == ToneOperator::None && exposure == 1.f) return;  // nothing to do: skip the pass
    parallelFor(0, image.height(), 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* p = image.row(y);
            for (int i = 0; i < image.width() * 4; ++i) {
                if (i % 4 == 3) continue;  // alpha untouched
                const float x = std::max(0.f, p[i] * exposure);
                p[i] = op == ToneOperator::Aces     ? acesFitted(x)
                       : op == ToneOperator::Filmic ? hableFilmic(x)
                                                    : x;
            }
        }
    });
}

}  // namespace flarekit
