// EXT_mesh_gpu_instancing: a node's instances load as objects of their own, as the same scene written with a node
// per instance does, and a bad instancing object is refused naming its JSON pointer.
#include "GltfLoaderFixture.hpp"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstring>
#include <limits>

namespace penumbra::scene {
namespace {

using testing::InstanceAttributes;

// Three instances: one left alone, one turned and stretched, one turned 60 degrees about (1, 2, 3) and mirrored.
InstanceAttributes threeInstances(Component rotation = Component::Float)
{
    return {.translations = {{0, 0, 0}, {3, 0, 0}, {0, 2, -4}},
            .rotations = {{0, 0, 0, 1},
                          {0, 0.7071068f, 0, 0.7071068f},
                          {0.1336306f, 0.2672612f, 0.4008919f, 0.8660254f}},
            .scales = {{1, 1, 1}, {2, 0.5f, 1}, {-1, 1, 1}},
            .rotationComponent = rotation};
}

// The instanced node moves and stretches its instances, its parent moves and turns it.
nlohmann::json parentNode(int child)
{
    return {{"name", "parent"},
            {"translation", {1, 2, 3}},
            {"rotation", {0, 0, 0.3826834, 0.9238795}},
            {"children", {child}}};
}

nlohmann::json treesNode()
{
    return {{"name", "trees"}, {"mesh", 0}, {"translation", {0, 1, 0}}, {"scale", {1, 2, 1}}};
}

// Node 0 "trees" instances the cube (accessors 0 to 3) with accessors 4 on (TRANSLATION, ROTATION, SCALE, those
// given); node 1 is its parent.
GltfBuilder instancedScene(const InstanceAttributes& instances)
{
    GltfBuilder b;
    testing::addCubeMesh(b, "Cube", -1);
    b.addRoot(b.add("nodes", parentNode(testing::addInstancedNode(b, treesNode(), instances))));
    return b;
}

template <int N>
nlohmann::json arrayOf(const glm::vec<N, float>& v)
{
    nlohmann::json out = nlohmann::json::array();
    for (int c = 0; c < N; ++c)
        out.push_back(v[c]);
    return out;
}

// The same scene without the extension: the instanced node gets a child per instance with the instance's transform.
GltfBuilder plainScene(const InstanceAttributes& instances)
{
    GltfBuilder b;
    testing::addCubeMesh(b, "Cube", -1);
    const std::size_t count =
        std::max({instances.translations.size(), instances.rotations.size(), instances.scales.size()});
    nlohmann::json trees = treesNode();
    trees.erase("mesh");
    for (std::size_t i = 0; i < count; ++i) {
        nlohmann::json child = {{"name", fmt::format("trees/instance {}", i)}, {"mesh", 0}};
        if (!instances.translations.empty())
            child["translation"] = arrayOf(instances.translations[i]);
        if (!instances.rotations.empty())
            child["rotation"] = arrayOf(instances.rotations[i]);
        if (!instances.scales.empty())
            child["scale"] = arrayOf(instances.scales[i]);
        trees["children"].push_back(b.add("nodes", child));
    }
    b.addRoot(b.add("nodes", parentNode(b.add("nodes", trees))));
    return b;
}

void expectSameObjects(const Scene& instanced, const Scene& plain, float tolerance)
{
    ASSERT_EQ(instanced.objects.size(), plain.objects.size());
    EXPECT_EQ(instanced.meshes.size(), plain.meshes.size());
    for (std::size_t o = 0; o < plain.objects.size(); ++o) {
        const Object& a = instanced.objects[o];
        const Object& b = plain.objects[o];
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(a.mesh, b.mesh) << a.name;
        EXPECT_EQ(a.material, b.material) << a.name;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                EXPECT_NEAR(a.transform[c][r], b.transform[c][r], tolerance) << a.name << " " << c << "," << r;
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_NEAR(a.worldBounds.min[axis], b.worldBounds.min[axis], 4.0f * tolerance) << a.name;
            EXPECT_NEAR(a.worldBounds.max[axis], b.worldBounds.max[axis], 4.0f * tolerance) << a.name;
        }
    }
}

std::string joinedNotes(const std::vector<std::string>& notes)
{
    std::string out;
    for (const std::string& note : notes)
        out += note + "\n";
    return out;
}

TEST_F(GltfLoaderTest, InstancesLoadAsTheObjectsOfANodePerInstance)
{
    GltfBuilder instanced = instancedScene(threeInstances());
    ASSERT_EQ(instanced.json()["extensionsRequired"], nlohmann::json::array({"EXT_mesh_gpu_instancing"}));
    const gltf::GltfScene loaded = gltf::loadGltf(write(instanced, "instanced.gltf"));
    expectSameObjects(loaded.scene, gltf::loadGltf(write(plainScene(threeInstances()), "plain.gltf")).scene, 1e-5f);
    ASSERT_EQ(loaded.scene.objects.size(), 3u);
    EXPECT_EQ(loaded.scene.objects[2].name, "trees/instance 2");
    // One mesh for the two unmirrored instances, a copy with reversed winding for the mirrored one.
    EXPECT_EQ(loaded.scene.meshes.size(), 2u);
    EXPECT_EQ(loaded.scene.objects[0].mesh, loaded.scene.objects[1].mesh);
    EXPECT_NE(loaded.scene.objects[0].mesh, loaded.scene.objects[2].mesh);
    // Instance 1 by hand: its own scale, turn and move, then the node's, then the parent's.
    const glm::mat4 parent = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) *
                             glm::mat4_cast(glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 0, 1)));
    const glm::mat4 node = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 0)), glm::vec3(1, 2, 1));
    const glm::mat4 instance = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(3, 0, 0)) *
                                              glm::mat4_cast(glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0))),
                                          glm::vec3(2, 0.5f, 1));
    const glm::mat4 expected = parent * node * instance;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(loaded.scene.objects[1].transform[c][r], expected[c][r], 1e-5f) << c << "," << r;
}

TEST_F(GltfLoaderTest, MissingInstanceAttributesAreTheIdentity)
{
    const InstanceAttributes all = threeInstances();
    const std::vector<InstanceAttributes> partial{{.translations = all.translations},
                                                  {.rotations = all.rotations},
                                                  {.scales = all.scales}};
    for (std::size_t i = 0; i < partial.size(); ++i) {
        SCOPED_TRACE(i);
        expectSameObjects(gltf::loadGltf(write(instancedScene(partial[i]), "instanced.gltf")).scene,
                          gltf::loadGltf(write(plainScene(partial[i]), "plain.gltf")).scene, 1e-5f);
    }
}

TEST_F(GltfLoaderTest, NormalizedByteAndShortRotationsAreDecoded)
{
    const Scene exact = gltf::loadGltf(write(instancedScene(threeInstances()), "float.gltf")).scene;
    // Rounding each component to a step of the integer type (1/32767, 1/127) turns an instance by up to about a step;
    // times the scales (up to 2 by the instance and 2 by the node) the transforms differ by a few steps (here at
    // most 4.2e-5 for SHORT, 1.8e-3 for BYTE).
    expectSameObjects(gltf::loadGltf(write(instancedScene(threeInstances(Component::Short)), "short.gltf")).scene,
                      exact, 1e-4f);
    expectSameObjects(gltf::loadGltf(write(instancedScene(threeInstances(Component::Byte)), "byte.gltf")).scene, exact,
                      5e-3f);
}

TEST_F(GltfLoaderTest, InstancesInheritTheNodesShadowExtras)
{
    GltfBuilder b;
    testing::addCubeMesh(b, "Cube", -1);
    nlohmann::json trees = treesNode();
    trees["extras"]["penumbra"] = {{"mobility", "dynamic"}};
    nlohmann::json parent = parentNode(testing::addInstancedNode(b, trees, threeInstances()));
    parent["extras"]["penumbra"] = {{"castShadows", "shadowsOnly"}, {"receiveShadows", false}};
    b.addRoot(b.add("nodes", parent));
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    ASSERT_EQ(loaded.scene.objects.size(), 3u);
    for (const Object& object : loaded.scene.objects) {
        EXPECT_EQ(object.castShadows, ShadowCasting::ShadowsOnly) << object.name;
        EXPECT_FALSE(object.receiveShadows) << object.name;
        EXPECT_EQ(object.mobility, Mobility::Dynamic) << object.name;
    }
}

TEST_F(GltfLoaderTest, InstancesOfAMeshOfTwoPrimitivesAreNamedByInstanceAndPrimitive)
{
    GltfBuilder b = instancedScene(threeInstances());
    b.json()["meshes"][0]["primitives"].push_back(b.json()["meshes"][0]["primitives"][0]);
    const Scene scene = gltf::loadGltf(write(b)).scene;
    ASSERT_EQ(scene.objects.size(), 6u);
    EXPECT_EQ(scene.objects[0].name, "trees/instance 0/0");
    EXPECT_EQ(scene.objects[3].name, "trees/instance 1/1");
}

TEST_F(GltfLoaderTest, InstancesScaledToNothingAndApplicationAttributesAreNoted)
{
    InstanceAttributes instances = threeInstances();
    instances.scales[1] = glm::vec3(0.0f);
    GltfBuilder b = instancedScene(instances);
    const std::vector<float> ids{7, 8, 9};
    b.json()["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["_ID"] =
        b.addAccessor({reinterpret_cast<const std::uint8_t*>(ids.data()), ids.size() * sizeof(float)}, ids.size(),
                      "SCALAR", Component::Float);
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    ASSERT_EQ(loaded.scene.objects.size(), 2u);
    EXPECT_EQ(loaded.scene.objects[1].name, "trees/instance 2");
    const std::string notes = joinedNotes(loaded.notes);
    EXPECT_CONTAINS(notes, "node 0 ('trees'): 1 of 3 instances skipped, their transforms scale them to nothing");
    EXPECT_CONTAINS(notes, "node 0 ('trees'): EXT_mesh_gpu_instancing attribute _ID is application-specific: ignored");
}

// Bad instancing: one GltfError naming the JSON pointer of what is wrong.

constexpr const char* kExtension = "scene.gltf: /nodes/0/extensions/EXT_mesh_gpu_instancing";

nlohmann::json& extensionOf(GltfBuilder& b) { return b.json()["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]; }

nlohmann::json& attributesOf(GltfBuilder& b) { return extensionOf(b)["attributes"]; }

TEST_F(GltfLoaderTest, BadInstanceAttributesAreNamedByTheirPointer)
{
    const auto errorWith = [&](const auto& change) {
        GltfBuilder b = instancedScene(threeInstances());
        change(b);
        return errorOf(write(b));
    };
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) { attributesOf(b)["TRANSLATION"] = 99; }),
                    fmt::format("{}/attributes/TRANSLATION: expected an index of accessors (the file has 7), got 99",
                                kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) { b.json()["accessors"][4]["type"] = "VEC4"; }),
                    fmt::format("{}/attributes/TRANSLATION: accessor 4 is VEC4 of component type 5126, which "
                                "TRANSLATION may not use",
                                kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) { b.json()["accessors"][5]["componentType"] = 5122; }),
                    fmt::format("{}/attributes/ROTATION: accessor 5 is VEC4 of component type 5122, which ROTATION may "
                                "not use",
                                kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) {
                        b.json()["accessors"][5]["componentType"] = 5123;
                        b.json()["accessors"][5]["normalized"] = true;
                    }),
                    fmt::format("{}/attributes/ROTATION: accessor 5 is VEC4 of component type 5123 (normalized), which "
                                "ROTATION may not use",
                                kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) {
                        b.json()["accessors"][6]["componentType"] = 5121;
                        b.json()["accessors"][6]["normalized"] = true;
                    }),
                    fmt::format("{}/attributes/SCALE: accessor 6 is VEC3 of component type 5121 (normalized), which "
                                "SCALE may not use",
                                kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) { b.json()["accessors"][6]["count"] = 2; }),
                    fmt::format("{}/attributes/SCALE: accessor 6 has 2 elements, other attributes 3", kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) { attributesOf(b)["COLOR"] = 4; }),
                    fmt::format("{}/attributes/COLOR: is not an EXT_mesh_gpu_instancing attribute", kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) { attributesOf(b) = nlohmann::json::object(); }),
                    fmt::format("{}/attributes: expected at least one attribute", kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) { extensionOf(b).erase("attributes"); }),
                    fmt::format("{}: the required property 'attributes' is missing", kExtension));
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) { b.json()["nodes"][0].erase("mesh"); }),
                    fmt::format("{}: the node has no mesh to instance", kExtension));
    // The cube's POSITION accessor, a VEC3 of FLOAT, as the only attribute.
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) {
                        attributesOf(b) = {{"TRANSLATION", 0}};
                    }),
                    fmt::format("{}/attributes/TRANSLATION: accessor 0 is also used as vertex attribute", kExtension));
    // Instance accessors go through the byte range checks of every accessor.
    EXPECT_CONTAINS(errorWith([](GltfBuilder& b) {
                        for (const int a : {4, 5, 6})
                            b.json()["accessors"][std::size_t(a)]["count"] = 4;
                    }),
                    "scene.gltf: /accessors/4/count: 4 elements need 48 bytes of buffer view 4, which has 36");
}

TEST_F(GltfLoaderTest, BadInstanceRotationsAreRefused)
{
    const std::string attributes = fmt::format("{}/attributes", kExtension);
    InstanceAttributes zero = threeInstances();
    zero.rotations[1] = glm::vec4(0.0f);
    EXPECT_CONTAINS(errorOf(write(instancedScene(zero))),
                    attributes + ": accessor 5 (ROTATION) element 1 has length 0, expected a unit quaternion");
    InstanceAttributes longer = threeInstances();
    longer.rotations[2] = glm::vec4(0, 0, 0, 1.5f);
    EXPECT_CONTAINS(errorOf(write(instancedScene(longer))),
                    attributes + ": accessor 5 (ROTATION) element 2 has length 1.5, expected a unit quaternion");
    GltfBuilder b = instancedScene(threeInstances());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::size_t view = b.json()["accessors"][5]["bufferView"];
    std::memcpy(b.bin().data() + b.json()["bufferViews"][view]["byteOffset"].get<std::size_t>() + 16, &nan, sizeof nan);
    EXPECT_CONTAINS(errorOf(write(b)), attributes + ": accessor 5 (ROTATION) element 1 is not finite");
}

TEST_F(GltfLoaderTest, TooManyInstancesInAllAreRefused)
{
    GltfBuilder b = instancedScene({.translations = {{0, 0, 0}}});
    // 60 000 zero translations without a buffer view, on this node and on a second one.
    b.json()["accessors"][4].erase("bufferView");
    b.json()["accessors"][4]["count"] = 60000;
    b.addRoot(b.add("nodes", b.json()["nodes"][0]));
    EXPECT_CONTAINS(errorOf(write(b)), "scene.gltf: /nodes/2/extensions/EXT_mesh_gpu_instancing: the file's instanced "
                                       "nodes reach 120000 instances here, over the limit of 100000");
    b.json()["accessors"][4]["count"] = 50000;
    EXPECT_EQ(gltf::loadGltf(write(b)).scene.objects.size(), 100000u);
}

} // namespace
} // namespace penumbra::scene
