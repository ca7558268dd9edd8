#pragma once

#include "penumbra/scene/Rig.hpp"

#include <cstdint>

namespace penumbra::viewer {

// Which of the scene's glTF animations the viewer plays, where in it, and whether time runs. Space plays and pauses,
// `,` and `.` step back and forth by kScrubSeconds (pausing), `[` and `]` pick the previous and next animation; the
// panel's "animation" header lists the animations and scrubs with a slider. The scene is posed from it every frame
// (scene::poseScene, skinned on the GPU).
struct AnimationPlayer {
    static constexpr float kScrubSeconds = 0.1f;

    std::uint32_t animation = 0; // a scene::Rig::animations index
    float time = 0.0f; // seconds into it, from 0 to its duration
    bool playing = true;

    // Moves time on by `seconds` while playing, looping at the end of the animation.
    void advance(float seconds, const scene::Rig& rig);
    // Steps time by `steps` * kScrubSeconds, within 0 and the duration, and pauses.
    void scrub(int steps, const scene::Rig& rig);
    // The animation `steps` further on in the rig's list (wrapping), from its start.
    void pick(int steps, const scene::Rig& rig);
};

} // namespace penumbra::viewer
