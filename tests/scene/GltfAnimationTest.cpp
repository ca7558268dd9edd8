// Skins, morph targets and animations read from hand-built files and posed at known times.
#include "GltfAnimationScenes.hpp"
#include "GltfLoaderFixture.hpp"

#include "penumbra/scene/Posing.hpp"

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

namespace penumbra::scene {
namespace {

constexpr float kTolerance = 1e-5f;

// The posed bar's vertex `index` (the bar's mesh keeps the file's vertex order).
glm::vec3 barVertex(const Scene& scene, std::size_t index)
{
    const Object& bar = scene.objects[*scene.findObject("bar")];
    return glm::vec3(bar.transform * glm::vec4(scene.meshOf(bar).vertices[index].position, 1.0f));
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected)
{
    EXPECT_NEAR(actual.x, expected.x, kTolerance);
    EXPECT_NEAR(actual.y, expected.y, kTolerance);
    EXPECT_NEAR(actual.z, expected.z, kTolerance);
}

using GltfAnimationTest = GltfLoaderTest;

TEST_F(GltfAnimationTest, TwoBoneBendPutsTheTopVertexWhereTheJointsSay)
{
    gltf::GltfScene loaded = gltf::loadGltf(write(testing::twoBoneBendScene()));
    Scene& scene = loaded.scene;
    ASSERT_EQ(scene.rig.skins.size(), 1u);
    ASSERT_EQ(scene.rig.animations.size(), 2u);
    for (const std::string& note : loaded.notes)
        EXPECT_EQ(note.find("tolerated"), std::string::npos) << note;
    expectNear(barVertex(scene, 8), glm::vec3(0.1f, 2.0f, 0.1f));
    const std::uint32_t bend = findAnimation(scene.rig, "bend");
    poseScene(scene, bend, 1.0f);
    expectNear(barVertex(scene, 8), glm::vec3(-1.0f, 1.1f, 0.1f));
    // Ring 1 follows both joints by half: (0.1, 1, 0.1) and (0, 1.1, 0.1).
    expectNear(barVertex(scene, 4), glm::vec3(0.05f, 1.05f, 0.1f));
    const float c = std::cos(glm::quarter_pi<float>()), s = std::sin(glm::quarter_pi<float>());
    poseScene(scene, bend, 0.5f);
    expectNear(barVertex(scene, 8), glm::vec3(0.1f * c - s, 1.0f + 0.1f * s + c, 0.1f));
    // The bounds follow the pose, so culling and shadow fitting see it.
    const Object& bar = scene.objects[*scene.findObject("bar")];
    EXPECT_NEAR(bar.worldBounds.min.x, -0.1f * c - s, kTolerance); // corner (-0.1, 2) turned 45 degrees
    EXPECT_EQ(bar.mobility, Mobility::Dynamic);
    EXPECT_EQ(scene.objects[*scene.findObject("ground")].mobility, Mobility::Static);
    // By index and clamped after the last key.
    poseScene(scene, findAnimation(scene.rig, "0"), 7.0f);
    expectNear(barVertex(scene, 8), glm::vec3(-1.0f, 1.1f, 0.1f));
}

TEST_F(GltfAnimationTest, TwoBoneBendNormalsTurnWithTheElbow)
{
    gltf::GltfScene loaded = gltf::loadGltf(write(testing::twoBoneBendScene()));
    poseScene(loaded.scene, 0u, 1.0f);
    const Object& bar = loaded.scene.objects[*loaded.scene.findObject("bar")];
    // Vertex 8's normal (1, 0, 1) / sqrt 2 turned 90 degrees about z: (0, 1, 1) / sqrt 2.
    const glm::vec3 normal = loaded.scene.meshOf(bar).vertices[8].normal;
    expectNear(normal, glm::vec3(0.0f, std::sqrt(0.5f), std::sqrt(0.5f)));
}

TEST_F(GltfAnimationTest, AnimationsAreChosenByNameAndStepHoldsItsKey)
{
    gltf::GltfScene loaded = gltf::loadGltf(write(testing::twoBoneBendScene()));
    Scene& scene = loaded.scene;
    poseScene(scene, findAnimation(scene.rig, "lift"), 0.49f);
    expectNear(barVertex(scene, 0), glm::vec3(0.1f, 0.0f, 0.1f));
    poseScene(scene, findAnimation(scene.rig, "lift"), 0.5f);
    expectNear(barVertex(scene, 0), glm::vec3(0.1f, 1.0f, 0.1f));
    EXPECT_THROW(findAnimation(scene.rig, "walk"), SceneError);
    EXPECT_THROW(findAnimation(scene.rig, "2"), SceneError);
}

TEST_F(GltfAnimationTest, NormalizedByteWeightsPoseAsFloatOnes)
{
    gltf::GltfScene floats = gltf::loadGltf(write(testing::twoBoneBendScene(), "floats.gltf"));
    gltf::GltfScene bytes =
        gltf::loadGltf(write(testing::twoBoneBendScene(testing::BendWeights::UnsignedByte), "bytes.gltf"));
    poseScene(floats.scene, 0u, 1.0f);
    poseScene(bytes.scene, 0u, 1.0f);
    // 128 / 255 and 127 / 255 instead of halves: ring 1 moves by less than a 255th of the joints' difference.
    for (std::size_t v = 0; v < 12; ++v) {
        const glm::vec3 a = barVertex(floats.scene, v), b = barVertex(bytes.scene, v);
        EXPECT_LT(glm::length(a - b), 0.01f) << "vertex " << v;
    }
}

// glTF 2.0 section 3.7.3.3 says weights sum to 1; an exporter's that do not are divided by their sum (as three.js's
// GLTFLoader does), with a note naming the accessor, so the file poses as its normalized twin.
TEST_F(GltfAnimationTest, WeightsThatDoNotSumToOneAreNormalizedWithANote)
{
    gltf::GltfScene loaded = gltf::loadGltf(write(testing::twoBoneBendScene(testing::BendWeights::Unnormalized)));
    const auto note = std::find_if(loaded.notes.begin(), loaded.notes.end(), [](const std::string& n) {
        return n.find("(WEIGHTS_0) element 0: weights sum to 0.78") != std::string::npos;
    });
    ASSERT_NE(note, loaded.notes.end()) << ::testing::PrintToString(loaded.notes);
    poseScene(loaded.scene, 0u, 1.0f);
    expectNear(barVertex(loaded.scene, 8), glm::vec3(-1.0f, 1.1f, 0.1f));
    expectNear(barVertex(loaded.scene, 4), glm::vec3(0.05f, 1.05f, 0.1f));
}

TEST_F(GltfAnimationTest, MorphTargetsBlendDefaultAndAnimatedWeights)
{
    gltf::GltfScene loaded = gltf::loadGltf(write(testing::morphScene()));
    Scene& scene = loaded.scene;
    ASSERT_EQ(scene.rig.deformers.size(), 1u);
    const glm::vec3 rest = scene.rig.deformers[0].rest[0].position;
    const MeshData& mesh = scene.meshOf(scene.objects[0]);
    // Mesh weights (0.5, 0): half of target 0.
    expectNear(mesh.vertices[0].position, rest + glm::vec3(0.0f, 0.0f, 0.5f));
    expectNear(mesh.vertices[1].position, scene.rig.deformers[0].rest[1].position);
    // At t = 1 the weights are (0.5, 0.25).
    poseScene(scene, findAnimation(scene.rig, "morph"), 1.0f);
    expectNear(mesh.vertices[0].position, rest + glm::vec3(0.0f, 0.25f, 0.5f));
    EXPECT_NEAR(mesh.bounds.max.z, 0.5f, kTolerance);
}

TEST_F(GltfAnimationTest, StepAndCubicSplineChannelsMoveTheirNodes)
{
    gltf::GltfScene loaded = gltf::loadGltf(write(testing::keyframeScene()));
    Scene& scene = loaded.scene;
    const auto x = [&](const char* name) { return scene.objects[*scene.findObject(name)].transform[3].x; };
    poseScene(scene, 0u, 1.5f);
    EXPECT_FLOAT_EQ(x("step"), 5.0f);
    poseScene(scene, 0u, 1.0f);
    EXPECT_FLOAT_EQ(x("spline"), 1.5f); // KeyframesTest's hand computation
    EXPECT_FLOAT_EQ(x("step"), 5.0f);
    poseScene(scene, 0u, 0.5f);
    EXPECT_FLOAT_EQ(x("step"), 0.0f);
    EXPECT_NEAR(scene.objects[*scene.findObject("step")].worldBounds.max.x, 1.0f, kTolerance);
}

TEST_F(GltfAnimationTest, AnAnimatedCameraIsNotedAsStayingInItsRestPose)
{
    GltfBuilder b = testing::twoBoneBendScene();
    nlohmann::json& j = b.json();
    // The camera node "side" (the last root) carried by the elbow.
    const int camera = j["scenes"][0]["nodes"].back();
    j["scenes"][0]["nodes"].erase(j["scenes"][0]["nodes"].size() - 1);
    for (nlohmann::json& node : j["nodes"])
        if (node.value("name", "") == "elbow")
            node["children"] = {camera};
    const gltf::GltfScene loaded = gltf::loadGltf(write(b));
    EXPECT_NE(std::find(loaded.notes.begin(), loaded.notes.end(),
                        fmt::format("node {} ('side'): the camera is animated, which is not supported: it stays in "
                                    "its rest pose",
                                    camera)),
              loaded.notes.end())
        << ::testing::PrintToString(loaded.notes);
}

TEST_F(GltfAnimationTest, BadSkinsAndAnimationsAreRefusedNamingTheAccessor)
{
    const auto refused = [&](const std::function<void(nlohmann::json&)>& edit, const std::string& expected) {
        GltfBuilder b = testing::twoBoneBendScene();
        edit(b.json());
        const std::string error = errorOf(write(b));
        EXPECT_NE(error.find(expected), std::string::npos) << "error: " << error;
    };
    // Accessor 3 is JOINTS_0: a single joint leaves joint 1 out of range.
    refused(
        [](nlohmann::json& j) { j["skins"][0]["joints"] = {1}; },
        "mesh 0 ('bar') primitive 0: accessor 3 (JOINTS_0) element 0 refers to joint 1 but skin 'arm' has 1 joints");
    refused([](nlohmann::json& j) { j["accessors"][std::size_t(j["skins"][0]["inverseBindMatrices"])]["count"] = 1; },
            "skin 0 ('arm'): accessor 5 (inverseBindMatrices) has 1 elements but the skin has 2 joints");
    const auto bendInput = [](nlohmann::json& j) -> nlohmann::json& {
        return j["accessors"][std::size_t(j["animations"][0]["samplers"][0]["input"])];
    };
    refused([&](nlohmann::json& j) { j["animations"][0]["samplers"][0]["interpolation"] = "CUBICSPLINE"; },
            "animation 0 ('bend') sampler 0: accessor 11 (output) has 8 components, expected 24 (2 keys x 4 x 3");
    refused([&](nlohmann::json& j) { bendInput(j).erase("min"); },
            "/animations/0/samplers/0/input: accessor 10 has no min and max");
    refused([](nlohmann::json& j) { j["animations"][0]["channels"][0]["target"]["path"] = "weights"; },
            "animation 0 ('bend') channel 0: animates the weights of node 0, which has no morph targets");
    refused([](nlohmann::json& j) { j["animations"][0]["channels"][0]["target"]["path"] = "scale"; },
            "animation 0 ('bend') sampler 0: accessor 11 (output) is VEC4 of FLOAT, expected VEC3 of FLOAT");
    refused([](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["attributes"].erase("JOINTS_0"); },
            "mesh 0 ('bar') primitive 0: has no JOINTS_0, but its node has a skin");
}

TEST_F(GltfAnimationTest, KeyTimesThatDoNotIncreaseAreRefused)
{
    GltfBuilder b = testing::keyframeScene();
    // The STEP sampler's times 0, 1, 2 become 0, 1, 1.
    const int input = b.json()["animations"][0]["samplers"][0]["input"];
    const int view = b.json()["accessors"][std::size_t(input)]["bufferView"];
    const std::size_t offset = b.json()["bufferViews"][std::size_t(view)]["byteOffset"];
    const float one = 1.0f;
    std::memcpy(b.bin().data() + offset + 8, &one, sizeof one);
    b.json()["accessors"][std::size_t(input)]["max"] = {1.0};
    EXPECT_EQ(errorOf(write(b)).substr(errorOf(write(b)).find(": ") + 2),
              fmt::format("animation 0 ('keys') sampler 0: accessor {} (input) element 2 is 1, not after the previous "
                          "key's 1",
                          input));
}

} // namespace
} // namespace penumbra::scene
