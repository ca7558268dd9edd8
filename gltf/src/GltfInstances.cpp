#include "GltfInstances.hpp"

#include "GltfAccessors.hpp"
#include "GltfNodes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace penumbra::gltf {
namespace {

// How far a quantized quaternion's length may be from 1 by rounding alone: each of its four components is off by
// at most half a step of the integer type, so the length by at most one step.
double quantizationStep(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return 1.0 / 127.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return 1.0 / 32767.0;
    default:
        return 0.0;
    }
}

std::vector<glm::quat> readUnitQuaternions(const Document& document, int accessor, const std::string& owner)
{
    const double tolerance =
        kUnitLengthTolerance + quantizationStep(document.model().accessors[std::size_t(accessor)].componentType);
    std::vector<glm::quat> out;
    const std::vector<glm::vec4> values = readRotations(document, accessor, owner, "ROTATION");
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double length = glm::length(glm::dvec4(values[i]));
        if (std::abs(length - 1.0) > tolerance)
            document.fail(fmt::format("{}: accessor {} (ROTATION) element {} has length {}, expected a unit quaternion",
                                      owner, accessor, i, length));
        // glTF stores x, y, z, w; glm::quat takes w first.
        out.push_back(glm::normalize(glm::quat(values[i].w, values[i].x, values[i].y, values[i].z)));
    }
    return out;
}

} // namespace

std::optional<Instances> readInstances(const Document& document, const tinygltf::Node& node, int index)
{
    const auto extension = node.extensions.find("EXT_mesh_gpu_instancing");
    if (extension == node.extensions.end())
        return std::nullopt;
    const std::string owner = fmt::format("/nodes/{}/extensions/EXT_mesh_gpu_instancing/attributes", index);
    const tinygltf::Value& attributes = extension->second.Get("attributes");
    Instances instances;
    std::vector<glm::vec3> translations, scales;
    std::vector<glm::quat> rotations;
    std::size_t count = 0;
    for (const std::string& name : attributes.Keys()) {
        const int accessor = attributes.Get(name).GetNumberAsInt();
        count = accessorCount(document, accessor, owner);
        if (name == "TRANSLATION")
            translations = readVec3(document, accessor, owner, name);
        else if (name == "ROTATION")
            rotations = readUnitQuaternions(document, accessor, owner);
        else if (name == "SCALE")
            scales = readVec3(document, accessor, owner, name);
        else
            instances.ignored.push_back(name);
    }
    instances.transforms.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
        instances.transforms.push_back(
            trsTransform(translations.empty() ? glm::vec3(0.0f) : translations[i],
                         rotations.empty() ? glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : rotations[i],
                         scales.empty() ? glm::vec3(1.0f) : scales[i]));
    return instances;
}

} // namespace penumbra::gltf
