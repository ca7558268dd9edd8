#pragma once

#include "GltfDocument.hpp"

#include "penumbra/scene/Scene.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <vector>

namespace penumbra::gltf {

// A camera node met while walking the scene, with its world transform.
struct CameraInstance {
    int camera;
    int node;
    glm::mat4 world;
};

// A KHR_lights_punctual light node with its world transform.
struct LightInstance {
    int light;
    int node;
    glm::mat4 world;
};

// What walking the default scene's node trees (or, without scenes, every root node) finds.
struct NodeWalk {
    std::vector<CameraInstance> cameras;
    std::vector<LightInstance> lights;
};

// Adds an object per primitive of every mesh node to `scene` (meshes, materials and textures as
// they are first used), one per instance of an EXT_mesh_gpu_instancing node, and collects camera and
// light nodes. Throws GltfError for a node index out of range, a node that is its own ancestor, or a
// bad mesh or instance; notes skipped nodes and instances and ignored instance attributes.
NodeWalk walkNodes(const Document& document, scene::Scene& scene, std::vector<std::string>& notes);

// The node's local transform: its matrix, or translation * rotation * scale.
glm::mat4 localTransform(const tinygltf::Node& node);

// translation * rotation * scale, the order of glTF 2.0 section 3.5.3; `rotation` is a unit quaternion.
glm::mat4 trsTransform(const glm::vec3& translation, const glm::quat& rotation, const glm::vec3& scale);

} // namespace penumbra::gltf
