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

// An object made for a node's mesh primitive: what posing it at another time needs to know.
struct ObjectSource {
    std::uint32_t object;
    int node;
    int mesh;
    int primitive;
    glm::mat4 instance; // EXT_mesh_gpu_instancing's transform of the instance, identity otherwise
};

// What walking the default scene's node trees (or, without scenes, every root node) finds.
struct NodeWalk {
    std::vector<CameraInstance> cameras;
    std::vector<LightInstance> lights;
    std::vector<ObjectSource> objects;
};

// Adds an object per primitive of every mesh node to `scene` (meshes, materials and textures as
// they are first used), one per instance of an EXT_mesh_gpu_instancing node, and collects camera and
// light nodes. A skinned or morphed primitive gets a mesh of its own per object (it is deformed per pose), placed
// without its node's transform when skinned (glTF 2.0 section 3.7.3.1: the joints place it). Throws GltfError for a
// node index out of range, a node that is its own ancestor, or a bad mesh or instance; notes skipped nodes and
// instances and ignored instance attributes.
NodeWalk walkNodes(const Document& document, scene::Scene& scene, std::vector<std::string>& notes);

// The node's local transform: its matrix, or translation * rotation * scale.
glm::mat4 localTransform(const tinygltf::Node& node);

// translation * rotation * scale, the order of glTF 2.0 section 3.5.3; `rotation` is a unit quaternion.
glm::mat4 trsTransform(const glm::vec3& translation, const glm::quat& rotation, const glm::vec3& scale);

} // namespace penumbra::gltf
