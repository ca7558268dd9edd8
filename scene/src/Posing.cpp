#include "penumbra/scene/Posing.hpp"

#include "penumbra/scene/Keyframes.hpp"
#include "penumbra/scene/Skinning.hpp"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <charconv>
#include <string>

namespace penumbra::scene {

NodePose restPose(const Rig& rig)
{
    NodePose pose;
    for (const RigNode& node : rig.nodes) {
        pose.translations.push_back(node.translation);
        pose.rotations.push_back(node.rotation);
        pose.scales.push_back(node.scale);
        pose.weights.push_back(node.weights);
    }
    return pose;
}

void applyAnimation(const Animation& animation, float time, NodePose& pose)
{
    for (const AnimationChannel& channel : animation.channels) {
        const Keyframes& keys = animation.samplers[channel.sampler];
        switch (channel.path) {
        case AnimatedPath::Translation:
        case AnimatedPath::Scale: {
            const std::vector<float> v = sampleKeyframes(keys, time);
            (channel.path == AnimatedPath::Translation ? pose.translations : pose.scales)[channel.node] =
                glm::vec3(v[0], v[1], v[2]);
            break;
        }
        case AnimatedPath::Rotation:
            pose.rotations[channel.node] = sampleRotation(keys, time);
            break;
        case AnimatedPath::Weights:
            pose.weights[channel.node] = sampleKeyframes(keys, time);
            break;
        }
    }
}

std::vector<glm::mat4> worldTransforms(const Rig& rig, const NodePose& pose)
{
    std::vector<glm::mat4> world(rig.nodes.size());
    for (std::size_t n = 0; n < rig.nodes.size(); ++n) {
        const RigNode& node = rig.nodes[n];
        const glm::mat4 local =
            node.matrix
                ? *node.matrix
                : glm::scale(glm::translate(glm::mat4(1.0f), pose.translations[n]) * glm::mat4_cast(pose.rotations[n]),
                             pose.scales[n]);
        world[n] = node.parent >= 0 ? world[std::size_t(node.parent)] * local : local;
    }
    return world;
}

std::uint32_t findAnimation(const Rig& rig, std::string_view nameOrIndex)
{
    for (std::size_t a = 0; a < rig.animations.size(); ++a)
        if (rig.animations[a].name == nameOrIndex)
            return std::uint32_t(a);
    std::uint32_t index = 0;
    const char* end = nameOrIndex.data() + nameOrIndex.size();
    if (const auto [ptr, error] = std::from_chars(nameOrIndex.data(), end, index);
        error == std::errc() && ptr == end && index < rig.animations.size())
        return index;
    std::string names;
    for (std::size_t a = 0; a < rig.animations.size(); ++a)
        names += fmt::format("{}{} '{}'", a == 0 ? "" : ", ", a, rig.animations[a].name);
    throw SceneError(fmt::format("no animation named or numbered '{}'; the scene's animations: {}", nameOrIndex,
                                 names.empty() ? "none" : names));
}

void poseScene(Scene& scene, std::optional<std::uint32_t> animation, float time)
{
    Rig& rig = scene.rig;
    NodePose pose = restPose(rig);
    if (animation)
        applyAnimation(rig.animations.at(*animation), time, pose);
    const std::vector<glm::mat4> world = worldTransforms(rig, pose);
    const auto place = [&](std::uint32_t index, const glm::mat4& transform) {
        Object& object = scene.objects[index];
        object.transform = transform;
        object.worldBounds = scene.meshes[object.mesh].bounds.transformed(transform);
    };
    for (const PlacedObject& placed : rig.placed)
        place(placed.object, world[placed.node] * placed.instance);
    ++scene.revision;
    rig.pose.joints.clear();
    for (const Skin& skin : rig.skins)
        rig.pose.joints.push_back(jointMatrices(skin, world));
    rig.pose.weights.clear();
    for (const Deformer& deformer : rig.deformers) {
        const std::vector<float>& weights = pose.weights[deformer.node];
        rig.pose.weights.push_back(weights);
        MeshData& mesh = scene.meshes[scene.objects[deformer.object].mesh];
        mesh.vertices =
            deformVertices(deformer, weights,
                           deformer.skin >= 0 ? std::span<const glm::mat4>(rig.pose.joints[std::size_t(deformer.skin)])
                                              : std::span<const glm::mat4>());
        updateBounds(mesh);
        // glTF 2.0 section 3.7.3.1: a skinned mesh's node transform is ignored, its joints place it.
        place(deformer.object, deformer.skin >= 0 ? deformer.instance : world[deformer.node] * deformer.instance);
    }
}

} // namespace penumbra::scene
