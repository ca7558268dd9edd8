#pragma once

#include "penumbra/scene/Rig.hpp"
#include "penumbra/scene/Scene.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace penumbra::scene {

// Every rig node's local transform and morph weights at one moment.
struct NodePose {
    std::vector<glm::vec3> translations;
    std::vector<glm::quat> rotations;
    std::vector<glm::vec3> scales;
    std::vector<std::vector<float>> weights;
};

// The nodes as the file places them, with their default morph weights.
NodePose restPose(const Rig& rig);

// Overwrites what each of the animation's channels drives with its value at `time` (clamped to its keys).
void applyAnimation(const Animation& animation, float time, NodePose& pose);

// Each node's world transform: parent's world * local, local = its matrix or T * R * S (glTF 2.0 section 3.5.3).
std::vector<glm::mat4> worldTransforms(const Rig& rig, const NodePose& pose);

// The animation called `nameOrIndex`, or numbered so when no animation has that name. Throws SceneError naming
// the animations the scene has.
std::uint32_t findAnimation(const Rig& rig, std::string_view nameOrIndex);

// Poses the scene: its rest pose with `animation` (a Rig::animations index, none: the rest pose) applied at `time`
// seconds. Placed objects get their node's world transform, deformed ones their morphed and skinned vertices, and
// both their bounds, so culling and shadow fitting see the pose; Rig::pose takes the joint matrices and morph weights
// that the renderer's GPU skinning deforms the uploaded rest vertices with. The CPU path is the reference: the ground
// truth's ray caster reads these vertices, and the GPU skinning matches them.
void poseScene(Scene& scene, std::optional<std::uint32_t> animation, float time);

} // namespace penumbra::scene
