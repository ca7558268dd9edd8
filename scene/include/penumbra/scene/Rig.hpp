#pragma once

#include "penumbra/scene/Geometry.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::scene {

// What a scene keeps of a glTF file's node hierarchy to pose it again at another time: the nodes with their rest
// transforms, skins, the meshes that skins and morph targets deform (with their rest vertices) and the animations.
// Empty for a scene without skins, morph targets or animations; Scene::objects hold the pose last computed
// (Posing.hpp's poseScene), the rest pose after loading. The renderer's GPU skinning (render/src/skinning) uploads the
// rest vertices, per vertex joint indices and weights and per morph target the vertex offsets, and reads `pose`.

// A node of the hierarchy. `parent` is less than the node's own index, so one pass in order computes world transforms.
struct RigNode {
    std::string name;
    std::int32_t parent = -1; // -1: a root
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    // A node given by a matrix: its local transform. glTF 2.0 section 3.11: animated nodes use TRS, never a matrix.
    std::optional<glm::mat4> matrix;
    // The morph target weights of its mesh when no animation sets them: node.weights, else mesh.weights, else zeros.
    std::vector<float> weights;
};

// glTF 2.0 section 3.7.3: joint matrix j = world(joints[j]) * inverseBind[j].
struct Skin {
    std::string name;
    std::vector<std::uint32_t> joints; // RigNode indices
    std::vector<glm::mat4> inverseBind; // one per joint; identity where the file gives none
};

// Offsets a morph target adds, times its weight, to each vertex of the deformed mesh (empty: the target moves none).
struct MorphTarget {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec3> tangents;
};

// An object whose mesh a skin or morph targets deform: Scene::meshes[object's mesh] is its own (never shared), and is
// recomputed from `rest` at each pose.
struct Deformer {
    std::uint32_t object = 0; // Scene::objects index
    std::uint32_t node = 0; // the RigNode that draws it (its weights, and its transform without a skin)
    glm::mat4 instance{1.0f}; // EXT_mesh_gpu_instancing's per-instance transform, after the node's
    std::int32_t skin = -1; // Rig::skins index, -1 for morph targets only
    std::vector<Vertex> rest; // the vertices as the file gives them, before morphing and skinning
    // Four joints and four weights per set per vertex: set s of vertex v at [v * influenceSets + s] (JOINTS_s,
    // WEIGHTS_s). Joint indices are into Skin::joints; the weights of a vertex sum to 1.
    std::uint32_t influenceSets = 0;
    std::vector<glm::uvec4> joints;
    std::vector<glm::vec4> weights;
    std::vector<MorphTarget> targets;
    // The primitive had no normals: each triangle's vertices get its face normal again after deforming.
    bool flatNormals = false;
};

// An object placed by a node, not deformed: its transform is world(node) * instance.
struct PlacedObject {
    std::uint32_t object = 0;
    std::uint32_t node = 0;
    glm::mat4 instance{1.0f};
};

// glTF 2.0 section 3.11 and Appendix C, animation.sampler.interpolation.
enum class Interpolation : std::uint8_t { Linear, Step, CubicSpline };

// What a channel drives (animation.channel.target.path).
enum class AnimatedPath : std::uint8_t { Translation, Rotation, Scale, Weights };

// An animation sampler: key times (seconds, increasing) and `width` components per value; rotations as x, y, z, w.
// CubicSpline keeps three values per key: in-tangent, value, out-tangent.
struct Keyframes {
    std::vector<float> times;
    std::vector<float> values;
    std::uint32_t width = 0;
    Interpolation interpolation = Interpolation::Linear;
};

struct AnimationChannel {
    std::uint32_t node = 0; // RigNode index
    AnimatedPath path = AnimatedPath::Translation;
    std::uint32_t sampler = 0; // Animation::samplers index
};

struct Animation {
    std::string name;
    std::vector<Keyframes> samplers;
    std::vector<AnimationChannel> channels;
    // The last key time of all samplers: after it every channel holds its last value.
    float duration() const;
};

// The pose poseScene computed last, as the renderer's GPU skinning reads it: each skin's joint matrices
// (jointMatrices) and each deformer's morph weights, in Rig::skins and Rig::deformers order. Empty before a pose.
struct RigPose {
    std::vector<std::vector<glm::mat4>> joints;
    std::vector<std::vector<float>> weights;
};

struct Rig {
    std::vector<RigNode> nodes;
    std::vector<Skin> skins;
    std::vector<Deformer> deformers;
    std::vector<PlacedObject> placed;
    std::vector<Animation> animations;
    RigPose pose;

    bool empty() const { return nodes.empty(); }
};

} // namespace penumbra::scene
