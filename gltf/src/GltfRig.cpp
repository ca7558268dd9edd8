#include "GltfRig.hpp"

#include "GltfAccessors.hpp"

#include "penumbra/scene/Posing.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>

namespace penumbra::gltf {
namespace {

constexpr std::array<int, 1> kFloatComponent{TINYGLTF_COMPONENT_TYPE_FLOAT};
constexpr std::array<int, 2> kJointTypes{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
constexpr std::array<int, 3> kWeightTypes{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
// An inverse bind matrix's last row must be (0, 0, 0, 1) to this tolerance (gltf-validator ACCESSOR_INVALID_IBM).
constexpr float kAffineTolerance = 1e-6f;

int attribute(const std::map<std::string, int>& attributes, const std::string& name)
{
    const auto found = attributes.find(name);
    return found == attributes.end() ? -1 : found->second;
}

bool usesRig(const tinygltf::Model& model)
{
    return !model.skins.empty() || !model.animations.empty() ||
           std::any_of(model.meshes.begin(), model.meshes.end(),
                       [](const tinygltf::Mesh& mesh) { return targetCount(mesh) > 0; });
}

// Every node of the file, parents before children (roots in index order, each tree depth first); `rigNode` maps a
// glTF node to its place. The validated hierarchy has no loops and one parent per node.
std::vector<scene::RigNode> readNodes(const Document& document, std::vector<std::uint32_t>& rigNode)
{
    const tinygltf::Model& model = document.model();
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (const int child : model.nodes[n].children)
            parent[std::size_t(child)] = int(n);
    std::vector<scene::RigNode> nodes;
    rigNode.assign(model.nodes.size(), 0);
    std::vector<int> stack;
    for (std::size_t root = model.nodes.size(); root-- > 0;)
        if (parent[root] < 0)
            stack.push_back(int(root));
    while (!stack.empty()) {
        const int index = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = model.nodes[std::size_t(index)];
        scene::RigNode out;
        out.name = node.name;
        out.parent =
            parent[std::size_t(index)] < 0 ? -1 : std::int32_t(rigNode[std::size_t(parent[std::size_t(index)])]);
        if (node.matrix.size() == 16) {
            out.matrix = localTransform(node);
        } else {
            if (node.translation.size() == 3)
                out.translation =
                    glm::vec3(float(node.translation[0]), float(node.translation[1]), float(node.translation[2]));
            if (node.rotation.size() == 4)
                out.rotation = glm::normalize(glm::quat(float(node.rotation[3]), float(node.rotation[0]),
                                                        float(node.rotation[1]), float(node.rotation[2])));
            if (node.scale.size() == 3)
                out.scale = glm::vec3(float(node.scale[0]), float(node.scale[1]), float(node.scale[2]));
        }
        if (node.mesh >= 0) {
            const tinygltf::Mesh& mesh = model.meshes[std::size_t(node.mesh)];
            const std::vector<double>& defaults = !node.weights.empty() ? node.weights : mesh.weights;
            out.weights.assign(targetCount(mesh), 0.0f);
            for (std::size_t t = 0; t < defaults.size() && t < out.weights.size(); ++t)
                out.weights[t] = float(defaults[t]);
        }
        rigNode[std::size_t(index)] = std::uint32_t(nodes.size());
        nodes.push_back(std::move(out));
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back(*child);
    }
    (void)document;
    return nodes;
}

std::vector<scene::Skin> readSkins(const Document& document, const std::vector<std::uint32_t>& rigNode)
{
    std::vector<scene::Skin> skins;
    const tinygltf::Model& model = document.model();
    for (std::size_t s = 0; s < model.skins.size(); ++s) {
        const tinygltf::Skin& skin = model.skins[s];
        const std::string owner = describe("skin", int(s), skin.name);
        scene::Skin out{.name = skin.name, .joints = {}, .inverseBind = {}};
        for (const int joint : skin.joints) {
            document.at(model.nodes, joint, "node", owner);
            out.joints.push_back(rigNode[std::size_t(joint)]);
        }
        out.inverseBind.assign(out.joints.size(), glm::mat4(1.0f));
        if (skin.inverseBindMatrices >= 0) {
            const std::vector<float> values =
                readComponents(document, skin.inverseBindMatrices, owner, "inverseBindMatrices", TINYGLTF_TYPE_MAT4,
                               kFloatComponent);
            const std::size_t count = values.size() / 16;
            if (count < out.joints.size())
                document.fail(fmt::format("{}: accessor {} (inverseBindMatrices) has {} elements but the skin has {} "
                                          "joints",
                                          owner, skin.inverseBindMatrices, count, out.joints.size()));
            for (std::size_t j = 0; j < out.joints.size(); ++j) {
                const glm::mat4 m = glm::make_mat4(values.data() + 16 * j);
                if (std::abs(m[0][3]) > kAffineTolerance || std::abs(m[1][3]) > kAffineTolerance ||
                    std::abs(m[2][3]) > kAffineTolerance || std::abs(m[3][3] - 1.0f) > kAffineTolerance)
                    document.fail(fmt::format("{}: accessor {} (inverseBindMatrices) element {} is not an affine "
                                              "transform (its last row is not 0, 0, 0, 1)",
                                              owner, skin.inverseBindMatrices, j));
                out.inverseBind[j] = m;
            }
        }
        skins.push_back(std::move(out));
    }
    return skins;
}

// Which glTF vertex each scene vertex of a primitive came from: the same one, or, for flat normals, the triangle
// corner's index (readPrimitive gives each triangle vertices of its own).
std::vector<std::uint32_t> sourceVertices(const Document& document, const tinygltf::Primitive& primitive,
                                          std::size_t sceneVertices, const std::string& owner)
{
    std::vector<std::uint32_t> source;
    if (primitive.attributes.count("NORMAL") || primitive.indices < 0) {
        source.resize(sceneVertices);
        std::iota(source.begin(), source.end(), 0u);
        return source;
    }
    return readIndices(document, primitive.indices, owner);
}

class DeformerReader {
public:
    DeformerReader(const Document& document, std::vector<std::string>& notes) : document_(document), notes_(notes) {}

    scene::Deformer read(const ObjectSource& source, const scene::Scene& scene, const std::vector<scene::Skin>& skins)
    {
        const tinygltf::Model& model = document_.model();
        const tinygltf::Node& node = model.nodes[std::size_t(source.node)];
        const tinygltf::Mesh& mesh = model.meshes[std::size_t(source.mesh)];
        const tinygltf::Primitive& primitive = mesh.primitives[std::size_t(source.primitive)];
        const std::string owner =
            fmt::format("{} primitive {}", describe("mesh", source.mesh, mesh.name), source.primitive);
        scene::Deformer deformer;
        deformer.object = source.object;
        deformer.instance = source.instance;
        deformer.skin = node.skin;
        deformer.rest = scene.meshes[scene.objects[source.object].mesh].vertices;
        deformer.flatNormals = !primitive.attributes.count("NORMAL");
        const std::vector<std::uint32_t> from = sourceVertices(document_, primitive, deformer.rest.size(), owner);
        if (node.skin >= 0)
            readInfluences(primitive, owner, skins[std::size_t(node.skin)], from, deformer);
        for (std::size_t t = 0; t < primitive.targets.size(); ++t)
            deformer.targets.push_back(readTarget(primitive.targets[t], owner, t, from, deformer.flatNormals));
        return deformer;
    }

private:
    void readInfluences(const tinygltf::Primitive& primitive, const std::string& owner, const scene::Skin& skin,
                        const std::vector<std::uint32_t>& from, scene::Deformer& deformer)
    {
        std::uint32_t sets = 0;
        while (primitive.attributes.count(fmt::format("JOINTS_{}", sets)))
            ++sets;
        if (sets == 0)
            document_.fail(fmt::format("{}: has no JOINTS_0, but its node has a skin", owner));
        const std::size_t vertices = accessorCount(document_, attribute(primitive.attributes, "POSITION"), owner);
        deformer.influenceSets = sets;
        deformer.joints.assign(from.size() * sets, glm::uvec4(0));
        deformer.weights.assign(from.size() * sets, glm::vec4(0.0f));
        std::vector<float> sums(vertices, 0.0f);
        std::vector<glm::uvec4> joints(vertices * sets);
        std::vector<glm::vec4> weights(vertices * sets);
        for (std::uint32_t s = 0; s < sets; ++s) {
            const std::string jointName = fmt::format("JOINTS_{}", s), weightName = fmt::format("WEIGHTS_{}", s);
            const int jointAccessor = attribute(primitive.attributes, jointName);
            const int weightAccessor = attribute(primitive.attributes, weightName);
            if (weightAccessor < 0)
                document_.fail(fmt::format("{}: has {} but no {}", owner, jointName, weightName));
            const std::vector<float> j =
                readComponents(document_, jointAccessor, owner, jointName, TINYGLTF_TYPE_VEC4, kJointTypes);
            const std::vector<float> w =
                readComponents(document_, weightAccessor, owner, weightName, TINYGLTF_TYPE_VEC4, kWeightTypes);
            for (const auto& [accessor, name, count] : {std::tuple(jointAccessor, jointName, j.size() / 4),
                                                        std::tuple(weightAccessor, weightName, w.size() / 4)})
                if (count != vertices)
                    document_.fail(fmt::format("{}: accessor {} ({}) has {} elements but POSITION has {}", owner,
                                               accessor, name, count, vertices));
            for (std::size_t v = 0; v < vertices; ++v)
                for (int c = 0; c < 4; ++c) {
                    const auto joint = std::uint32_t(j[4 * v + std::size_t(c)]);
                    const float weight = w[4 * v + std::size_t(c)];
                    if (weight < 0.0f)
                        document_.fail(fmt::format("{}: accessor {} ({}) element {} has the negative weight {}", owner,
                                                   weightAccessor, weightName, v, weight));
                    // glTF 2.0 section 3.7.3.3: every joint index, whatever its weight, is one of the skin's joints.
                    if (joint >= skin.joints.size())
                        document_.fail(fmt::format("{}: accessor {} ({}) element {} refers to joint {} but {} has {} "
                                                   "joints",
                                                   owner, jointAccessor, jointName, v, joint,
                                                   skin.name.empty() ? "the skin" : fmt::format("skin '{}'", skin.name),
                                                   skin.joints.size()));
                    joints[v * sets + s][c] = joint;
                    weights[v * sets + s][c] = weight;
                    sums[v] += weight;
                }
        }
        normalizeWeights(primitive, owner, sums, sets, weights);
        for (std::size_t v = 0; v < from.size(); ++v)
            for (std::uint32_t s = 0; s < sets; ++s) {
                deformer.joints[v * sets + s] = joints[std::size_t(from[v]) * sets + s];
                deformer.weights[v * sets + s] = weights[std::size_t(from[v]) * sets + s];
            }
    }

    // glTF 2.0 section 3.7.3.3: a vertex's weights sum to 1 (exactly 255 or 65535 for normalized integers). Sums off
    // by more than the validator's rounding tolerance are exporter errors that would pull the vertex towards the
    // skeleton's origin; like three.js's GLTFLoader (SkinnedMesh.normalizeSkinWeights, three.js issue 15319) they are
    // divided by their sum, and a vertex whose weights are all 0 (the validator accepts an accessor of zeros) follows
    // its first joint alone, with a note naming the accessor.
    void normalizeWeights(const tinygltf::Primitive& primitive, const std::string& owner,
                          const std::vector<float>& sums, std::uint32_t sets, std::vector<glm::vec4>& weights)
    {
        const int accessor = attribute(primitive.attributes, "WEIGHTS_0");
        for (std::size_t v = 0; v < sums.size(); ++v) {
            if (std::abs(sums[v] - 1.0f) > kWeightSumTolerance && notedWeights_.insert(accessor).second)
                notes_.push_back(fmt::format("{}: accessor {} (WEIGHTS_0) element {}: weights sum to {}, not 1: "
                                             "normalized (and every other such vertex of the primitive){}",
                                             owner, accessor, v, sums[v],
                                             sums[v] > 0.0f ? "" : "; a vertex of no weight follows its first joint"));
            if (sums[v] > 0.0f) {
                for (std::uint32_t s = 0; s < sets; ++s)
                    weights[v * sets + s] /= sums[v];
            } else {
                weights[v * sets] = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
            }
        }
    }

    scene::MorphTarget readTarget(const std::map<std::string, int>& target, const std::string& owner, std::size_t t,
                                  const std::vector<std::uint32_t>& from, bool flatNormals)
    {
        scene::MorphTarget out;
        for (const auto& [semantic, accessor] : target) {
            std::vector<glm::vec3>* into = semantic == "POSITION"  ? &out.positions
                                           : semantic == "NORMAL"  ? &out.normals
                                           : semantic == "TANGENT" ? &out.tangents
                                                                   : nullptr;
            if (!into) {
                if (ignoredTargets_.insert(semantic).second)
                    notes_.push_back(
                        fmt::format("{}: morph target attribute {} is not supported: ignored", owner, semantic));
                continue;
            }
            if (semantic == "NORMAL" && flatNormals)
                continue;
            const std::string name = fmt::format("target {} {}", t, semantic);
            const std::vector<glm::vec3> values = readVec3(document_, accessor, owner, name);
            into->resize(from.size());
            for (std::size_t v = 0; v < from.size(); ++v) {
                if (from[v] >= values.size())
                    document_.fail(fmt::format("{}: accessor {} ({}) has {} elements, fewer than POSITION", owner,
                                               accessor, name, values.size()));
                (*into)[v] = values[from[v]];
            }
        }
        return out;
    }

    // The weights' sum may differ from 1 by the rounding of four 8-bit weights and a little more.
    static constexpr float kWeightSumTolerance = 5e-3f;

    const Document& document_;
    std::vector<std::string>& notes_;
    std::set<int> notedWeights_;
    std::set<std::string> ignoredTargets_;
};

// Nodes an animation moves, and their descendants.
std::vector<bool> animatedNodes(const scene::Rig& rig)
{
    std::vector<bool> animated(rig.nodes.size(), false);
    for (const scene::Animation& animation : rig.animations)
        for (const scene::AnimationChannel& channel : animation.channels)
            animated[channel.node] = true;
    for (std::size_t n = 0; n < rig.nodes.size(); ++n)
        if (rig.nodes[n].parent >= 0 && animated[std::size_t(rig.nodes[n].parent)])
            animated[n] = true;
    return animated;
}

void markDynamic(scene::Scene& scene)
{
    const std::vector<bool> animated = animatedNodes(scene.rig);
    for (const scene::PlacedObject& placed : scene.rig.placed)
        if (animated[placed.node])
            scene.objects[placed.object].mobility = scene::Mobility::Dynamic;
    for (const scene::Deformer& deformer : scene.rig.deformers) {
        bool moves = animated[deformer.node];
        if (deformer.skin >= 0)
            for (const std::uint32_t joint : scene.rig.skins[std::size_t(deformer.skin)].joints)
                moves = moves || animated[joint];
        if (moves)
            scene.objects[deformer.object].mobility = scene::Mobility::Dynamic;
    }
}

// Posing moves objects only: an animated light or camera stays where the rest pose puts it.
void noteStillLightsAndCameras(const Document& document, const NodeWalk& walk, const scene::Rig& rig,
                               const std::vector<std::uint32_t>& rigNode, std::vector<std::string>& notes)
{
    const std::vector<bool> animated = animatedNodes(rig);
    const auto note = [&](int node, const char* what) {
        if (animated[rigNode[std::size_t(node)]])
            notes.push_back(fmt::format("{}: the {} is animated, which is not supported: it stays in its rest pose",
                                        describe("node", node, document.model().nodes[std::size_t(node)].name), what));
    };
    for (const LightInstance& light : walk.lights)
        note(light.node, "light");
    for (const CameraInstance& camera : walk.cameras)
        note(camera.node, "camera");
}

} // namespace

std::size_t targetCount(const tinygltf::Mesh& mesh)
{
    return mesh.primitives.empty() ? 0 : mesh.primitives.front().targets.size();
}

void readRig(const Document& document, const NodeWalk& walk, scene::Scene& scene, std::vector<std::string>& notes)
{
    const tinygltf::Model& model = document.model();
    if (!usesRig(model))
        return;
    scene::Rig& rig = scene.rig;
    std::vector<std::uint32_t> rigNode;
    rig.nodes = readNodes(document, rigNode);
    rig.skins = readSkins(document, rigNode);
    DeformerReader deformers(document, notes);
    for (const ObjectSource& source : walk.objects) {
        const tinygltf::Node& node = model.nodes[std::size_t(source.node)];
        const tinygltf::Mesh& mesh = model.meshes[std::size_t(source.mesh)];
        const auto rigIndex = rigNode[std::size_t(source.node)];
        if (node.skin < 0 && mesh.primitives[std::size_t(source.primitive)].targets.empty()) {
            rig.placed.push_back({source.object, rigIndex, source.instance});
            continue;
        }
        scene::Deformer deformer = deformers.read(source, scene, rig.skins);
        deformer.node = rigIndex;
        rig.deformers.push_back(std::move(deformer));
    }
    rig.animations = readAnimations(document, rigNode, notes);
    markDynamic(scene);
    noteStillLightsAndCameras(document, walk, rig, rigNode, notes);
    scene::poseScene(scene, std::nullopt, 0.0f);
}

} // namespace penumbra::gltf
