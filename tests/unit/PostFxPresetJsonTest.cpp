// SPDX-License-Identifier: Apache-2.0
// Post-process presets written as JSON (postFxPresetToJson, what the studio saves) and read back
// by the CLI's reader.
#include <gtest/gtest.h>

#include "flarekit/PostFxParams.h"

using namespace flarekit;

TEST(PostFxPreset, EveryShippedPresetWritesJsonThatReadsBackTheSame) {
    // The studio saves post-process presets with postFxPresetToJson; the CLI must read back the
    // very params (a ghost_series comes back as its ghosts).
    for (const std::string& name : shippedPostFxPresetNames()) {
        auto p = loadPostFxPreset(name);
        ASSERT_TRUE(p.ok()) << name;
        const std::string text = postFxPresetToJson(*p);
        auto again = parsePostFxPreset(text, name + ".json");
        ASSERT_TRUE(again.ok()) << name << ": " << again.error().message << "\n" << text;
        EXPECT_EQ(postFxPresetToJson(*again), text) << name;
        ASSERT_EQ(again->ghosts.size(), p->ghosts.size()) << name;
        for (std::size_t i = 0; i < p->ghosts.size(); ++i) {
            EXPECT_EQ(again->ghosts[i].scale, p->ghosts[i].scale) << name << " ghost " << i;
            EXPECT_EQ(again->ghosts[i].tint, p->ghosts[i].tint) << name << " ghost " << i;
        }
        EXPECT_EQ(again->bloom.levels, p->bloom.levels) << name;
        EXPECT_EQ(again->bright.threshold, p->bright.threshold) << name;
        EXPECT_EQ(again->halo.intensity, p->halo.intensity) << name;
        EXPECT_EQ(again->streaks.intensity, p->streaks.intensity) << name;
        EXPECT_EQ(again->tone.op, p->tone.op) << name;
        EXPECT_EQ(again->flareIntensity, p->flareIntensity) << name;
    }
}
