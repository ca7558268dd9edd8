#pragma once

#include "GltfDocument.hpp"

#include <glm/mat4x4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace penumbra::gltf {

// A node's EXT_mesh_gpu_instancing instances.
struct Instances {
    // Per instance, translation * rotation * scale in the node's space (EXT_mesh_gpu_instancing, "Transformation
    // Order"); a missing attribute is the identity.
    std::vector<glm::mat4> transforms;
    // Application-specific attributes ("_ID"), which nothing here reads.
    std::vector<std::string> ignored;
};

// The instances of the node `index`, or nullopt for a node without the extension. The JSON has passed
// checkInstancing; the accessors are read as GltfAccessors reads them, errors naming the attributes' JSON pointer.
// A ROTATION that is not a unit quaternion (the tolerance of node rotations, widened by the rounding of a normalized
// integer type) is refused; the others are normalized, as node rotations are.
std::optional<Instances> readInstances(const Document& document, const tinygltf::Node& node, int index);

} // namespace penumbra::gltf
