#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scene/Scene.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <string>
#include <type_traits>

namespace penumbra::scene {
namespace {

Scene twoObjectScene()
{
    Scene scene;
    const std::uint32_t box = scene.addMesh(makeBox({1, 1, 1}));
    const std::uint32_t plain = scene.addMaterial({.name = "plain"});
    scene.addObject("floor box", box, plain, glm::mat4(1.0f));
    scene.addObject("raised box", box, plain, glm::translate(glm::mat4(1.0f), glm::vec3(0, 3, 0)));
    scene.lights.push_back({.name = "sun"});
    return scene;
}

std::string validationMessage(const Scene& scene)
{
    try {
        scene.validate();
    } catch (const SceneError& error) {
        return error.what();
    }
    return {};
}

TEST(SceneTest, ValidSceneValidates)
{
    const Scene scene = twoObjectScene();
    EXPECT_NO_THROW(scene.validate());
    EXPECT_EQ(scene.findObject("raised box"), 1u);
    EXPECT_FALSE(scene.findObject("missing"));
}

TEST(SceneTest, AddObjectComputesWorldBounds)
{
    const Scene scene = twoObjectScene();
    EXPECT_EQ(scene.objects[1].worldBounds.min, glm::vec3(-1, 2, -1));
    EXPECT_EQ(scene.objects[1].worldBounds.max, glm::vec3(1, 4, 1));
    EXPECT_EQ(scene.worldBounds().min, glm::vec3(-1, -1, -1));
    EXPECT_EQ(scene.worldBounds().max, glm::vec3(1, 4, 1));
}

TEST(SceneTest, BadMeshReferenceNamesTheObject)
{
    Scene scene = twoObjectScene();
    scene.objects[1].mesh = 7;
    const std::string message = validationMessage(scene);
    EXPECT_NE(message.find("object 1 ('raised box')"), std::string::npos) << message;
    EXPECT_NE(message.find("mesh 7"), std::string::npos) << message;
}

TEST(SceneTest, BadMaterialReferenceNamesTheObject)
{
    Scene scene = twoObjectScene();
    scene.objects[0].material = 3;
    const std::string message = validationMessage(scene);
    EXPECT_NE(message.find("object 0"), std::string::npos) << message;
    EXPECT_NE(message.find("material 3"), std::string::npos) << message;
}

TEST(SceneTest, StaleWorldBoundsAreRejected)
{
    Scene scene = twoObjectScene();
    scene.objects[1].transform = glm::mat4(1.0f);
    const std::string message = validationMessage(scene);
    EXPECT_NE(message.find("object 1"), std::string::npos) << message;
    EXPECT_NE(message.find("stale"), std::string::npos) << message;
}

TEST(SceneTest, ProjectiveTransformsAreRejected)
{
    Scene scene = twoObjectScene();
    scene.objects[1].transform[2][3] = -1.0f;
    const std::string message = validationMessage(scene);
    EXPECT_NE(message.find("object 1 ('raised box')"), std::string::npos) << message;
    EXPECT_NE(message.find("last row is (0, 0, -1, 1)"), std::string::npos) << message;
}

TEST(SceneTest, BrokenMeshIndicesAndLightsAreRejected)
{
    Scene scene = twoObjectScene();
    scene.meshes[0].indices.back() = 1000;
    EXPECT_NE(validationMessage(scene).find("mesh 0"), std::string::npos);

    scene = twoObjectScene();
    scene.lights[0].direction = {0, -2, 0};
    EXPECT_NE(validationMessage(scene).find("light 0 ('sun')"), std::string::npos);

    EXPECT_THROW(scene.addObject("nothing", 5, 0, glm::mat4(1.0f)), SceneError);
    static_assert(std::is_base_of_v<std::runtime_error, SceneError>);
}

TEST(SceneTest, SpotAndPointLightsOutOfRangeAreRejectedByName)
{
    Scene scene = twoObjectScene();
    scene.spotLights.push_back({.name = "lamp", .innerAngle = 0.7f, .outerAngle = 0.5f});
    std::string message = validationMessage(scene);
    EXPECT_NE(message.find("spot light 0 ('lamp')"), std::string::npos) << message;
    EXPECT_NE(message.find("inner"), std::string::npos) << message;

    scene = twoObjectScene();
    scene.pointLights.push_back({.name = "bulb", .range = 0.0f});
    message = validationMessage(scene);
    EXPECT_NE(message.find("point light 0 ('bulb'): range"), std::string::npos) << message;

    scene = twoObjectScene();
    scene.pointLights.push_back({.name = "bulb", .range = 5.0f, .shadowNearPlane = 5.0f});
    message = validationMessage(scene);
    EXPECT_NE(message.find("point light 0 ('bulb'): shadowNearPlane 5 must be in [0, range 5)"), std::string::npos)
        << message;
}

TEST(MaterialTest, ClipAlphaIsACheckerOfBaseAlpha)
{
    const Material clip{.baseColor = {1, 1, 1, 0.8f}, .caster = CasterMode::Clip};
    const float cell = 1.0f / kClipCheckerCells;
    EXPECT_EQ(materialAlpha(clip, {0.5f * cell, 0.5f * cell}), 0.8f); // cell (0, 0): even
    EXPECT_EQ(materialAlpha(clip, {1.5f * cell, 0.5f * cell}), 0.0f); // cell (1, 0): odd, a hole
    EXPECT_EQ(materialAlpha(clip, {1.5f * cell, 1.5f * cell}), 0.8f); // cell (1, 1): even
    const Material dither{.baseColor = {1, 1, 1, 0.3f}, .caster = CasterMode::Dither};
    EXPECT_EQ(materialAlpha(dither, {1.5f * cell, 0.5f * cell}), 0.3f);
    EXPECT_EQ(materialAlpha(Material{}, {0.3f, 0.7f}), 1.0f);
}

TEST(MaterialTest, TexturedAlphaIsBilinearAndRepeats)
{
    // Two texels: alpha 0 on the left, 1 on the right; their centres at u = 0.25 and 0.75.
    const TextureImage texture{"edge", 2, 1, {255, 255, 255, 0, 255, 255, 255, 255}};
    const Material clip{.baseColor = {1, 1, 1, 0.8f}, .caster = CasterMode::Clip};
    EXPECT_FLOAT_EQ(materialAlpha(clip, {0.25f, 0.5f}, &texture), 0.0f);
    EXPECT_FLOAT_EQ(materialAlpha(clip, {0.75f, 0.5f}, &texture), 0.8f);
    EXPECT_FLOAT_EQ(materialAlpha(clip, {0.5f, 0.5f}, &texture), 0.4f);
    EXPECT_FLOAT_EQ(textureAlpha(texture, {1.0f, 0.5f}), 0.5f); // between the last texel and the first, repeated
    EXPECT_FLOAT_EQ(textureAlpha(texture, {-0.25f, 0.5f}), 1.0f); // the right texel, one period to the left
}

TEST(MaterialTest, CheckerIsSymmetricUnderAFaceMirror)
{
    // Opposite box faces run v (or u) in opposite directions; an odd cell count keeps the
    // holes of a thin clipped box lined up through both faces.
    const Material clip{.caster = CasterMode::Clip};
    for (float u = 0.01f; u < 1.0f; u += 0.047f)
        for (float v = 0.01f; v < 1.0f; v += 0.053f)
            EXPECT_EQ(materialAlpha(clip, {u, v}), materialAlpha(clip, {u, 1.0f - v})) << u << " " << v;
}

TEST(CameraTest, ViewPutsTheTargetOnTheNegativeZAxis)
{
    const Camera camera = lookAt({0, 8, -20}, {0, 0, 5}, glm::radians(60.0f));
    const glm::vec4 target = camera.view() * glm::vec4(0, 0, 5, 1);
    EXPECT_NEAR(target.x, 0.0f, 1e-5f);
    EXPECT_NEAR(target.y, 0.0f, 1e-5f);
    EXPECT_NEAR(target.z, -glm::length(glm::vec3(0, -8, 25)), 1e-4f);
    const glm::vec4 eye = camera.view() * glm::vec4(camera.position, 1);
    EXPECT_NEAR(glm::length(glm::vec3(eye)), 0.0f, 1e-5f);
    // Looking along +z with y up, +x is on the left: right() is -x.
    EXPECT_NEAR(glm::dot(camera.right(), glm::vec3(-1, 0, 0)), 1.0f, 1e-6f);
}

TEST(LightTest, DirectionFromPitchAndYaw)
{
    const glm::vec3 down = lightDirection(glm::half_pi<float>(), 0.0f);
    EXPECT_NEAR(down.y, -1.0f, 1e-6f);
    const glm::vec3 d = lightDirection(glm::radians(50.0f), glm::radians(90.0f));
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
    EXPECT_NEAR(d.x, std::cos(glm::radians(50.0f)), 1e-6f); // yaw 90 shines towards +x
    EXPECT_NEAR(d.z, 0.0f, 1e-6f);
    EXPECT_NEAR(d.y, -std::sin(glm::radians(50.0f)), 1e-6f);
}

} // namespace
} // namespace penumbra::scene
