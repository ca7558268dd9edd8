#include "AnimationPlayer.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::viewer {

void AnimationPlayer::advance(float seconds, const scene::Rig& rig)
{
    if (!playing || rig.animations.empty())
        return;
    const float duration = rig.animations[animation].duration();
    time = duration > 0.0f ? std::fmod(time + seconds, duration) : 0.0f;
}

void AnimationPlayer::scrub(int steps, const scene::Rig& rig)
{
    if (steps == 0 || rig.animations.empty())
        return;
    playing = false;
    time = std::clamp(time + float(steps) * kScrubSeconds, 0.0f, rig.animations[animation].duration());
}

void AnimationPlayer::pick(int steps, const scene::Rig& rig)
{
    if (steps == 0 || rig.animations.empty())
        return;
    const auto count = static_cast<int>(rig.animations.size());
    animation = static_cast<std::uint32_t>(((static_cast<int>(animation) + steps) % count + count) % count);
    time = 0.0f;
}

} // namespace penumbra::viewer
