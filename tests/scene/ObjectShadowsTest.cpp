// Per-object shadow choices (Object::castShadows, receiveShadows): what the ray caster sees, and how
// glTF nodes set them through extras.
#include "GltfLoaderFixture.hpp"

#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/truth/RayCaster.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {
namespace {

Scene boxWith(ShadowCasting casting, CasterMode materialMode = CasterMode::On)
{
    Scene scene;
    const std::uint32_t object = scene.addObject("box", scene.addMesh(makeBox({1, 1, 1})),
                                                 scene.addMaterial({.caster = materialMode}), glm::mat4(1.0f));
    scene.objects[object].castShadows = casting;
    return scene;
}

bool blocks(const Scene& scene, truth::RayKind kind)
{
    return truth::RayCaster(scene, kind).occluded({0, 0, -5}, {0, 0, 1});
}

TEST(ObjectShadowsTest, RayCasterSeesWhatEachModeDraws)
{
    for (const ShadowCasting casting : {ShadowCasting::On, ShadowCasting::TwoSided})
        EXPECT_TRUE(blocks(boxWith(casting), truth::RayKind::Shadow) &&
                    blocks(boxWith(casting), truth::RayKind::Camera))
            << shadowCastingName(casting);
    EXPECT_FALSE(blocks(boxWith(ShadowCasting::Off), truth::RayKind::Shadow));
    EXPECT_TRUE(blocks(boxWith(ShadowCasting::Off), truth::RayKind::Camera));
    EXPECT_TRUE(blocks(boxWith(ShadowCasting::ShadowsOnly), truth::RayKind::Shadow));
    EXPECT_FALSE(blocks(boxWith(ShadowCasting::ShadowsOnly), truth::RayKind::Camera));
    // The material's choice still holds: an object set to cast with a material that casts nothing casts nothing.
    EXPECT_FALSE(blocks(boxWith(ShadowCasting::On, CasterMode::Off), truth::RayKind::Shadow));
}

TEST(ObjectShadowsTest, SceneAsksBothObjectAndMaterial)
{
    Scene scene = boxWith(ShadowCasting::On);
    EXPECT_TRUE(scene.castsShadows(scene.objects[0]));
    EXPECT_TRUE(scene.receivesShadows(scene.objects[0]));
    scene.objects[0].receiveShadows = false;
    EXPECT_FALSE(scene.receivesShadows(scene.objects[0]));
    scene.objects[0].receiveShadows = true;
    scene.materials[0].receiveShadows = false;
    EXPECT_FALSE(scene.receivesShadows(scene.objects[0]));
    scene.objects[0].castShadows = ShadowCasting::Off;
    EXPECT_FALSE(scene.castsShadows(scene.objects[0]));
}

TEST(ObjectShadowsTest, NamesRoundTrip)
{
    for (const ShadowCasting casting :
         {ShadowCasting::On, ShadowCasting::Off, ShadowCasting::TwoSided, ShadowCasting::ShadowsOnly})
        EXPECT_EQ(parseShadowCasting(shadowCastingName(casting)), casting);
    EXPECT_FALSE(parseShadowCasting("two-sided"));
}

// A parent node (node 2) whose children (nodes 0 and 1) inherit its extras unless they set their own; null
// extras are left out.
GltfBuilder familyScene(const nlohmann::json& parentExtras, const nlohmann::json& childExtras)
{
    const auto withExtras = [](nlohmann::json node, const nlohmann::json& extras) {
        if (!extras.is_null())
            node["extras"] = extras;
        return node;
    };
    GltfBuilder b;
    const int mesh = testing::addCubeMesh(b, "Cube", -1, Component::UnsignedShort);
    const int plain = b.add("nodes", {{"name", "plain child"}, {"mesh", mesh}});
    const int own = b.add("nodes", withExtras({{"name", "own child"}, {"mesh", mesh}}, childExtras));
    b.addRoot(
        b.add("nodes", withExtras({{"name", "parent"}, {"mesh", mesh}, {"children", {plain, own}}}, parentExtras)));
    return b;
}

const Object& named(const Scene& scene, const char* name) { return scene.objects.at(*scene.findObject(name)); }

TEST_F(GltfLoaderTest, NodeExtrasSetShadowChoicesAndChildrenInheritThem)
{
    const gltf::GltfScene loaded =
        gltf::loadGltf(write(familyScene({{"penumbra", {{"castShadows", "shadowsOnly"}}}},
                                         {{"penumbra", {{"castShadows", "twoSided"}, {"receiveShadows", false}}}})));
    EXPECT_EQ(named(loaded.scene, "parent").castShadows, ShadowCasting::ShadowsOnly);
    EXPECT_TRUE(named(loaded.scene, "parent").receiveShadows);
    EXPECT_EQ(named(loaded.scene, "plain child").castShadows, ShadowCasting::ShadowsOnly);
    EXPECT_EQ(named(loaded.scene, "own child").castShadows, ShadowCasting::TwoSided);
    EXPECT_FALSE(named(loaded.scene, "own child").receiveShadows);
}

TEST_F(GltfLoaderTest, OtherToolsExtrasAreLeftAlone)
{
    const gltf::GltfScene loaded = gltf::loadGltf(write(familyScene({{"blenderProperty", 3}}, nullptr)));
    for (const Object& object : loaded.scene.objects) {
        EXPECT_EQ(object.castShadows, ShadowCasting::On);
        EXPECT_TRUE(object.receiveShadows);
    }
}

TEST_F(GltfLoaderTest, BadShadowExtrasAreNamedByTheirPointer)
{
    EXPECT_CONTAINS(errorOf(write(familyScene({{"penumbra", {{"castShadows", "sometimes"}}}}, nullptr), "a.gltf")),
                    "a.gltf: /nodes/2/extras/penumbra/castShadows: expected one of \"on\", \"off\", \"twoSided\"");
    EXPECT_CONTAINS(errorOf(write(familyScene(nullptr, {{"penumbra", {{"receiveShadows", 1}}}}), "b.gltf")),
                    "b.gltf: /nodes/1/extras/penumbra/receiveShadows: expected true or false");
    EXPECT_CONTAINS(errorOf(write(familyScene({{"penumbra", "off"}}, nullptr), "c.gltf")),
                    "c.gltf: /nodes/2/extras/penumbra: expected an object");
}

} // namespace
} // namespace penumbra::scene
