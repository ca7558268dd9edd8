// The viewer's animation playback (AnimationPlayer): playing loops over the duration, scrubbing pauses and stays
// within the animation, picking wraps around the list and starts the animation over.
#include "AnimationPlayer.hpp"

#include <gtest/gtest.h>

namespace penumbra::viewer {
namespace {

scene::Rig twoAnimations()
{
    scene::Rig rig;
    for (const float last : {2.0f, 0.5f})
        rig.animations.push_back({.name = "a", .samplers = {{.times = {0.0f, last}, .values = {0, 1}, .width = 1}}});
    return rig;
}

TEST(AnimationPlayerTest, PlaysLoopsScrubsAndPicks)
{
    const scene::Rig rig = twoAnimations();
    AnimationPlayer player;
    player.advance(1.5f, rig);
    EXPECT_FLOAT_EQ(player.time, 1.5f);
    player.advance(1.0f, rig);
    EXPECT_FLOAT_EQ(player.time, 0.5f) << "loops at the duration, 2 s";
    player.scrub(-10, rig);
    EXPECT_FALSE(player.playing);
    EXPECT_FLOAT_EQ(player.time, 0.0f) << "clamped at the start";
    player.advance(1.0f, rig);
    EXPECT_FLOAT_EQ(player.time, 0.0f) << "paused";
    player.scrub(3, rig);
    EXPECT_NEAR(player.time, 3 * AnimationPlayer::kScrubSeconds, 1e-6f);
    player.pick(-1, rig);
    EXPECT_EQ(player.animation, 1u);
    EXPECT_FLOAT_EQ(player.time, 0.0f);
    player.pick(1, rig);
    EXPECT_EQ(player.animation, 0u);
}

} // namespace
} // namespace penumbra::viewer
