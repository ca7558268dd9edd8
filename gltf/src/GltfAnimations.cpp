#include "GltfAccessors.hpp"
#include "GltfRig.hpp"

#include <array>
#include <map>
#include <optional>
#include <set>

namespace penumbra::gltf {
namespace {

constexpr std::array<int, 1> kAnimationFloat{TINYGLTF_COMPONENT_TYPE_FLOAT};
// glTF 2.0 section 3.11, table "animation.sampler.output": rotations and weights may be normalized integers.
constexpr std::array<int, 5> kAnimationFloatOrNormalized{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                         TINYGLTF_COMPONENT_TYPE_SHORT,
                                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};

std::optional<scene::AnimatedPath> pathOf(const std::string& path)
{
    if (path == "translation")
        return scene::AnimatedPath::Translation;
    if (path == "rotation")
        return scene::AnimatedPath::Rotation;
    if (path == "scale")
        return scene::AnimatedPath::Scale;
    if (path == "weights")
        return scene::AnimatedPath::Weights;
    return std::nullopt;
}

scene::Interpolation interpolationOf(const std::string& interpolation)
{
    if (interpolation == "STEP")
        return scene::Interpolation::Step;
    if (interpolation == "CUBICSPLINE")
        return scene::Interpolation::CubicSpline;
    return scene::Interpolation::Linear;
}

class AnimationReader {
public:
    AnimationReader(const Document& document, int index)
        : document_(document), animation_(document.model().animations[std::size_t(index)]),
          owner_(describe("animation", index, animation_.name))
    {
    }

    scene::Animation read(const std::vector<std::uint32_t>& rigNode, std::vector<std::string>& notes)
    {
        const tinygltf::Model& model = document_.model();
        scene::Animation out;
        out.name = animation_.name;
        std::set<std::pair<int, std::string>> targets;
        std::map<int, std::uint32_t> samplers; // glTF sampler -> out.samplers index
        for (std::size_t c = 0; c < animation_.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = animation_.channels[c];
            const std::string where = fmt::format("{} channel {}", owner_, c);
            if (channel.target_node < 0)
                continue;
            const std::optional<scene::AnimatedPath> animated = pathOf(channel.target_path);
            if (!animated) {
                notes.push_back(fmt::format("{}: path '{}' is not supported: ignored", where, channel.target_path));
                continue;
            }
            const scene::AnimatedPath path = *animated;
            const tinygltf::Node& node = document_.at(model.nodes, channel.target_node, "node", where);
            if (!targets.insert({channel.target_node, channel.target_path}).second)
                document_.fail(fmt::format("{}: node {} {} is already the target of another channel", where,
                                           channel.target_node, channel.target_path));
            // glTF 2.0 section 3.11: "When a node is targeted for animation ... matrix MUST NOT be present".
            if (node.matrix.size() == 16)
                document_.fail(fmt::format("{}: node {} has a matrix, and animated nodes may only have translation, "
                                           "rotation and scale",
                                           where, channel.target_node));
            std::size_t width = path == scene::AnimatedPath::Rotation ? 4 : 3;
            if (path == scene::AnimatedPath::Weights) {
                width = node.mesh < 0 ? 0 : targetCount(model.meshes[std::size_t(node.mesh)]);
                if (width == 0)
                    document_.fail(fmt::format("{}: animates the weights of node {}, which has no morph targets", where,
                                               channel.target_node));
            }
            const auto [found, fresh] = samplers.emplace(channel.sampler, std::uint32_t(out.samplers.size()));
            if (fresh)
                out.samplers.push_back(readSampler(channel.sampler, path, width));
            else if (out.samplers[found->second].width != width)
                document_.fail(fmt::format("{}: sampler {} also drives a channel of {} components, not {}", where,
                                           channel.sampler, out.samplers[found->second].width, width));
            out.channels.push_back({rigNode[std::size_t(channel.target_node)], path, found->second});
        }
        return out;
    }

private:
    scene::Keyframes readSampler(int index, scene::AnimatedPath path, std::size_t width)
    {
        const tinygltf::AnimationSampler& sampler = document_.at(animation_.samplers, index, "sampler", owner_);
        const std::string where = fmt::format("{} sampler {}", owner_, index);
        scene::Keyframes keys;
        keys.width = std::uint32_t(width);
        keys.interpolation = interpolationOf(sampler.interpolation);
        keys.times = readComponents(document_, sampler.input, where, "input", TINYGLTF_TYPE_SCALAR, kAnimationFloat);
        // glTF 2.0 section 3.11: times are seconds, time[0] >= 0 and strictly increasing.
        for (std::size_t k = 0; k < keys.times.size(); ++k) {
            if (keys.times[k] < 0.0f)
                document_.fail(fmt::format("{}: accessor {} (input) element {} is the negative time {}", where,
                                           sampler.input, k, keys.times[k]));
            if (k > 0 && keys.times[k] <= keys.times[k - 1])
                document_.fail(fmt::format("{}: accessor {} (input) element {} is {}, not after the previous key's {}",
                                           where, sampler.input, k, keys.times[k], keys.times[k - 1]));
        }
        const bool cubic = keys.interpolation == scene::Interpolation::CubicSpline;
        if (cubic && keys.times.size() < 2)
            document_.fail(fmt::format("{}: CUBICSPLINE needs at least 2 keys, accessor {} (input) has {}", where,
                                       sampler.input, keys.times.size()));
        const int type = path == scene::AnimatedPath::Weights    ? TINYGLTF_TYPE_SCALAR
                         : path == scene::AnimatedPath::Rotation ? TINYGLTF_TYPE_VEC4
                                                                 : TINYGLTF_TYPE_VEC3;
        const bool integers = path == scene::AnimatedPath::Weights || path == scene::AnimatedPath::Rotation;
        keys.values =
            integers ? readComponents(document_, sampler.output, where, "output", type, kAnimationFloatOrNormalized)
                     : readComponents(document_, sampler.output, where, "output", type, kAnimationFloat);
        const std::size_t expected = keys.times.size() * width * (cubic ? 3 : 1);
        if (keys.values.size() != expected)
            document_.fail(fmt::format("{}: accessor {} (output) has {} components, expected {} ({} keys x {}{})",
                                       where, sampler.output, keys.values.size(), expected, keys.times.size(), width,
                                       cubic ? " x 3 for CUBICSPLINE's tangents" : ""));
        return keys;
    }

    const Document& document_;
    const tinygltf::Animation& animation_;
    std::string owner_;
};

} // namespace

std::vector<scene::Animation> readAnimations(const Document& document, const std::vector<std::uint32_t>& rigNode,
                                             std::vector<std::string>& notes)
{
    std::vector<scene::Animation> animations;
    for (std::size_t a = 0; a < document.model().animations.size(); ++a)
        animations.push_back(AnimationReader(document, int(a)).read(rigNode, notes));
    return animations;
}

} // namespace penumbra::gltf
