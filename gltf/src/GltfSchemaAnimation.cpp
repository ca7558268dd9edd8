#include "GltfSchema.hpp"

#include <fmt/format.h>

namespace penumbra::gltf {
namespace {

// Accessor `index` read through `owner`'s `key` is of `type` with FLOAT components.
void requireFloat(const JsonFile& file, const Fields& owner, std::string_view key, int index, std::string_view type)
{
    const Json& accessor = accessorJson(file, index);
    if (accessor["type"] != type || accessor["componentType"] != kFloat)
        owner.fail(key, fmt::format("accessor {} is {} of component type {}, expected {} of FLOAT (5126)", index,
                                    accessor["type"].get<std::string>(), accessor["componentType"].get<std::int64_t>(),
                                    type));
}

void checkSkins(const JsonFile& file)
{
    for (const Fields& skin : topLevel(file, "skins")) {
        skin.require("joints");
        skin.indices("joints", "nodes");
        skin.index("skeleton", "nodes");
        if (const auto matrices = skin.index("inverseBindMatrices", "accessors"))
            requireFloat(file, skin, "inverseBindMatrices", *matrices, "MAT4");
    }
}

void checkAnimations(const JsonFile& file)
{
    for (const Fields& animation : topLevel(file, "animations")) {
        animation.require("channels");
        animation.require("samplers");
        const std::vector<Fields> samplers = animation.objects("samplers");
        for (const Fields& sampler : samplers) {
            sampler.require("input");
            sampler.require("output");
            const int input = *sampler.index("input", "accessors");
            sampler.index("output", "accessors");
            sampler.oneOf("interpolation", {"LINEAR", "STEP", "CUBICSPLINE"});
            requireFloat(file, sampler, "input", input, "SCALAR");
            // gltf-validator ANIMATION_SAMPLER_INPUT_ACCESSOR_WITHOUT_BOUNDS: input accessors declare min and max.
            if (!accessorJson(file, input).contains("min") || !accessorJson(file, input).contains("max"))
                sampler.fail("input",
                             fmt::format("accessor {} has no min and max, which animation inputs must have", input));
        }
        for (const Fields& channel : animation.objects("channels")) {
            channel.require("sampler");
            channel.require("target");
            channel.integer("sampler", 0, std::int64_t(samplers.size()) - 1);
            const Fields target = *channel.object("target");
            target.require("path");
            target.index("node", "nodes");
            // The schema's path is any string (extensions may add paths): the four of glTF 2.0 are read, others noted.
            target.string("path");
        }
    }
}

// glTF 2.0 section 3.7.2.2: every primitive of a mesh has as many morph targets, and default weights are one per
// target (gltf-validator MESH_PRIMITIVES_UNEQUAL_TARGETS_COUNT, MESH_INVALID_WEIGHTS_COUNT, NODE_WEIGHTS_INVALID).
void checkTargetCounts(const JsonFile& file)
{
    std::vector<std::size_t> targets;
    for (const Fields& mesh : topLevel(file, "meshes")) {
        std::optional<std::size_t> count;
        for (const Fields& primitive : mesh.objects("primitives")) {
            const std::size_t here = primitive.has("targets") ? primitive.json()["targets"].size() : 0;
            if (count && *count != here)
                primitive.fail("targets",
                               fmt::format("{} morph targets, other primitives of the mesh have {}", here, *count));
            count = here;
        }
        targets.push_back(count.value_or(0));
        if (mesh.has("weights") && mesh.json()["weights"].size() != targets.back())
            mesh.fail("weights",
                      fmt::format("{} weights for {} morph targets", mesh.json()["weights"].size(), targets.back()));
    }
    for (const Fields& node : topLevel(file, "nodes")) {
        const auto mesh = node.index("mesh", "meshes");
        if (mesh && node.has("weights") && node.json()["weights"].size() != targets[std::size_t(*mesh)])
            node.fail("weights", fmt::format("{} weights for the {} morph targets of mesh {}",
                                             node.json()["weights"].size(), targets[std::size_t(*mesh)], *mesh));
    }
}

} // namespace

void checkSkinsAndAnimations(const JsonFile& file)
{
    checkSkins(file);
    checkAnimations(file);
    checkTargetCounts(file);
}

} // namespace penumbra::gltf
