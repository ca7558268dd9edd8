#include "GltfNodes.hpp"

#include "GltfInstances.hpp"
#include "GltfLimits.hpp"
#include "GltfMaterials.hpp"
#include "GltfMeshes.hpp"
#include "GltfNodeShadows.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/common.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace penumbra::gltf {
namespace {

// Below this |determinant| a node is treated as scaled to nothing: its normal matrix (the
// inverse transpose) would not exist.
constexpr float kSingularDeterminant = 1e-12f;

class Walker {
public:
    Walker(const Document& document, scene::Scene& scene, std::vector<std::string>& notes)
        : document_(document), model_(document.model()), scene_(scene), notes_(notes),
          materials_(document, scene, notes), onPath_(model_.nodes.size(), false)
    {
    }

    void visit(int index, const glm::mat4& parent, const NodeShadows& parentShadows, const std::string& owner)
    {
        const tinygltf::Node& node = document_.at(model_.nodes, index, "node", owner);
        const auto slot = std::size_t(index);
        const std::string name = describe("node", index, node.name);
        if (onPath_[slot])
            document_.fail(fmt::format("{} is its own ancestor", name));
        onPath_[slot] = true;
        const glm::mat4 world = parent * localTransform(node);
        const NodeShadows shadows = readNodeShadows(document_, node, index, parentShadows);
        if (node.mesh >= 0)
            addMesh(index, node, world, shadows);
        if (node.camera >= 0) {
            document_.at(model_.cameras, node.camera, "camera", name);
            walk_.cameras.push_back({node.camera, index, world});
        }
        if (const auto light = node.extensions.find("KHR_lights_punctual"); light != node.extensions.end()) {
            const tinygltf::Value& value = light->second.Get("light");
            if (!value.IsInt() && !value.IsNumber())
                document_.fail(fmt::format("{}: KHR_lights_punctual has no light index", name));
            const int lightIndex = value.GetNumberAsInt();
            document_.at(model_.lights, lightIndex, "light", name);
            walk_.lights.push_back({lightIndex, index, world});
        }
        for (const int child : node.children)
            visit(child, world, shadows, name);
        onPath_[slot] = false;
    }

    NodeWalk result() { return std::move(walk_); }

private:
    void addMesh(int index, const tinygltf::Node& node, const glm::mat4& world, const NodeShadows& shadows)
    {
        const std::string name = describe("node", index, node.name);
        const tinygltf::Mesh& mesh = document_.at(model_.meshes, node.mesh, "mesh", name);
        const std::string base = node.name.empty() ? (mesh.name.empty() ? name : mesh.name) : node.name;
        const std::optional<Instances> instances = readInstances(document_, node, index);
        // glTF 2.0 section 3.7.3.1: a skinned mesh is placed by its joints, not by its node.
        const glm::mat4 placed = node.skin >= 0 ? glm::mat4(1.0f) : world;
        if (!instances) {
            if (!addPrimitives(index, node.mesh, mesh, base, placed, glm::mat4(1.0f), shadows))
                notes_.push_back(fmt::format("{}: skipped, its transform scales it to nothing", name));
            return;
        }
        for (const std::string& attribute : instances->ignored)
            if (ignoredAttributes_.insert(attribute).second)
                notes_.push_back(fmt::format("{}: EXT_mesh_gpu_instancing attribute {} is application-specific: "
                                             "ignored",
                                             name, attribute));
        // The extension's implementation note: "the non-instanced version of the mesh should not be rendered".
        std::size_t skipped = 0;
        for (std::size_t i = 0; i < instances->transforms.size(); ++i)
            skipped += !addPrimitives(index, node.mesh, mesh, fmt::format("{}/instance {}", base, i),
                                      placed * instances->transforms[i], instances->transforms[i], shadows);
        if (skipped > 0)
            notes_.push_back(fmt::format("{}: {} of {} instances skipped, their transforms scale them to nothing", name,
                                         skipped, instances->transforms.size()));
    }

    // An object per primitive of mesh `meshIndex` at `world`, named `base` (`base/<primitive>` for a mesh of more
    // than one); false, adding nothing, for a transform that scales the mesh to nothing.
    bool addPrimitives(int nodeIndex, int meshIndex, const tinygltf::Mesh& mesh, const std::string& base,
                       const glm::mat4& world, const glm::mat4& instance, const NodeShadows& shadows)
    {
        const bool skinned = model_.nodes[std::size_t(nodeIndex)].skin >= 0;
        const float determinant = glm::determinant(glm::mat3(world));
        if (std::abs(determinant) < kSingularDeterminant)
            return false;
        const bool mirrored = determinant < 0.0f;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            // glTF 2.0, section 3.7.2.1: without POSITION "the client implementation should skip the
            // primitive's rendering".
            if (!mesh.primitives[p].attributes.count("POSITION")) {
                if (positionless_.insert({meshIndex, int(p)}).second)
                    notes_.push_back(fmt::format("{} primitive {}: no POSITION attribute: skipped",
                                                 describe("mesh", meshIndex, mesh.name), p));
                continue;
            }
            const std::uint32_t material =
                materials_.material(mesh.primitives[p].material,
                                    fmt::format("{} primitive {}", describe("mesh", meshIndex, mesh.name), p));
            const auto key = std::make_tuple(meshIndex, int(p), mirrored);
            // A deformed mesh changes per pose, so it is never shared.
            const bool deformed = skinned || !mesh.primitives[p].targets.empty();
            const auto found = meshes_.find(key);
            std::uint32_t sceneMesh = found == meshes_.end() ? 0 : found->second;
            if (found == meshes_.end() || deformed) {
                const std::optional<scene::MaterialTexture>& normal =
                    scene_.materials[material].texture(scene::TextureSlot::Normal);
                scene::MeshData data = readPrimitive(document_, meshIndex, int(p),
                                                     normal ? std::optional(normal->texCoord) : std::nullopt);
                sceneMesh = scene_.addMesh(mirrored ? reversedWinding(std::move(data)) : std::move(data));
                if (!deformed)
                    meshes_.emplace(key, sceneMesh);
            }
            const std::uint32_t objectIndex =
                scene_.addObject(mesh.primitives.size() == 1 ? base : fmt::format("{}/{}", base, p), sceneMesh,
                                 material, world);
            walk_.objects.push_back({objectIndex, nodeIndex, meshIndex, int(p), instance});
            scene::Object& object = scene_.objects[objectIndex];
            checkWorldBounds(object, meshIndex, mesh, p);
            object.castShadows = shadows.cast;
            object.receiveShadows = shadows.receive;
            object.mobility = shadows.mobility;
        }
        return true;
    }

    // A node's transform may carry positions within kMaxCoordinate beyond it (or to infinity).
    void checkWorldBounds(const scene::Object& object, int meshIndex, const tinygltf::Mesh& mesh, std::size_t p) const
    {
        const glm::vec3 farthest = glm::max(glm::abs(object.worldBounds.min), glm::abs(object.worldBounds.max));
        if (glm::all(glm::lessThanEqual(farthest, glm::vec3(kMaxCoordinate))))
            return;
        document_.fail(fmt::format("{} primitive {}: accessor {} (POSITION) under the transform of object '{}' "
                                   "reaches ({:g}, {:g}, {:g}) in world space, over the limit of {:g} for a coordinate",
                                   describe("mesh", meshIndex, mesh.name), p,
                                   mesh.primitives[p].attributes.at("POSITION"), object.name, farthest.x, farthest.y,
                                   farthest.z, kMaxCoordinate));
    }

    const Document& document_;
    const tinygltf::Model& model_;
    scene::Scene& scene_;
    std::vector<std::string>& notes_;
    MaterialTable materials_;
    std::vector<bool> onPath_;
    std::map<std::tuple<int, int, bool>, std::uint32_t> meshes_; // (mesh, primitive, mirrored) -> scene mesh
    std::set<std::pair<int, int>> positionless_; // (mesh, primitive) noted as skipped
    std::set<std::string> ignoredAttributes_; // instance attributes noted as ignored
    NodeWalk walk_;
};

std::vector<int> rootNodes(const Document& document, std::vector<std::string>& notes)
{
    const tinygltf::Model& model = document.model();
    if (!model.scenes.empty()) {
        const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
        return document.at(model.scenes, scene, "scene", "the default scene").nodes;
    }
    notes.push_back("the file has no scenes: drawing every root node");
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes)
        for (const int child : node.children)
            if (child >= 0 && std::size_t(child) < isChild.size())
                isChild[std::size_t(child)] = true;
    std::vector<int> roots;
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        if (!isChild[i])
            roots.push_back(int(i));
    return roots;
}

} // namespace

glm::mat4 localTransform(const tinygltf::Node& node)
{
    if (node.matrix.size() == 16) {
        // The first three rows; the last is (0, 0, 0, 1), which the schema checks to within kAffineRowTolerance.
        glm::mat4 m(1.0f);
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 3; ++row)
                m[column][row] = float(node.matrix[std::size_t(column * 4 + row)]);
        return m;
    }
    const auto vec3 = [](const std::vector<double>& v, float fallback) {
        return v.size() == 3 ? glm::vec3(float(v[0]), float(v[1]), float(v[2])) : glm::vec3(fallback);
    };
    const std::vector<double>& r = node.rotation;
    // glTF stores x, y, z, w; glm::quat takes w first.
    const glm::quat rotation = r.size() == 4
                                   ? glm::normalize(glm::quat(float(r[3]), float(r[0]), float(r[1]), float(r[2])))
                                   : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    return trsTransform(vec3(node.translation, 0.0f), rotation, vec3(node.scale, 1.0f));
}

glm::mat4 trsTransform(const glm::vec3& translation, const glm::quat& rotation, const glm::vec3& scale)
{
    return glm::scale(glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation), scale);
}

NodeWalk walkNodes(const Document& document, scene::Scene& scene, std::vector<std::string>& notes)
{
    Walker walker(document, scene, notes);
    for (const int root : rootNodes(document, notes))
        walker.visit(root, glm::mat4(1.0f), NodeShadows{}, "the scene");
    return walker.result();
}

} // namespace penumbra::gltf
