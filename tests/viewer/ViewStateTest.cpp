#include "ViewState.hpp"

#include "penumbra/scenes/TestScenes.hpp"

#include <gtest/gtest.h>

namespace penumbra::viewer {
namespace {

struct Fixture {
    scene::Scene scene = scenes::makeShadowTestScene();
    ViewState applied;
    Fixture() { applied.lights = scene.lights; }
};

TEST(ViewStateTest, AValidEditIsAppliedToTheStateAndTheSceneWithDirectionsNormalised)
{
    Fixture f;
    ViewState edited = f.applied;
    edited.shadows.directional.cascadeCount = 2;
    edited.lights[0].direction = {0.0f, -2.0f, 0.0f};
    edited.lights[1].intensity = 3.0f;
    EXPECT_EQ(applyViewState(edited, f.applied, f.scene), "");
    EXPECT_EQ(f.applied.shadows.directional.cascadeCount, 2u);
    EXPECT_EQ(f.scene.lights[0].direction, glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_EQ(f.scene.lights[1].intensity, 3.0f);
}

TEST(ViewStateTest, ObjectShadowChoicesReachTheScene)
{
    scene::Scene scene = scenes::makeShadowTestScene();
    ViewState applied = viewStateOf(scene);
    ASSERT_EQ(applied.objects.size(), scene.objects.size());
    ViewState edited = applied;
    edited.objects[1] = {scene::ShadowCasting::ShadowsOnly, false};
    EXPECT_EQ(applyViewState(edited, applied, scene), "");
    EXPECT_EQ(scene.objects[1].castShadows, scene::ShadowCasting::ShadowsOnly);
    EXPECT_FALSE(scene.objects[1].receiveShadows);
    EXPECT_EQ(scene.objects[0].castShadows, scene::ShadowCasting::On);
}

TEST(ViewStateTest, SpotAndPointLightEditsReachTheSceneAndBadOnesAreRefused)
{
    scene::Scene scene = scenes::makeMixedLightsScene();
    ViewState applied = viewStateOf(scene);
    ViewState edited = applied;
    edited.spotLights[1].direction = {0.0f, -3.0f, 0.0f};
    edited.pointLights[0].range = 4.0f;
    edited.shadows.local.pointMode = shadows::PointShadowMode::CubeMap;
    EXPECT_EQ(applyViewState(edited, applied, scene), "");
    EXPECT_EQ(scene.spotLights[1].direction, glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_EQ(scene.pointLights[0].range, 4.0f);

    edited = applied;
    edited.spotLights[0].innerAngle = edited.spotLights[0].outerAngle + 0.1f;
    edited.pointLights[1].intensity = 9.0f;
    const std::string error = applyViewState(edited, applied, scene);
    EXPECT_NE(error.find("spot light 0"), std::string::npos) << error;
    EXPECT_NE(scene.pointLights[1].intensity, 9.0f);
    edited = applied;
    edited.shadows.local.cubeMapSize = 100;
    EXPECT_NE(applyViewState(edited, applied, scene).find("local.cubeMapSize"), std::string::npos);
}

TEST(ViewStateTest, ShadowSettingsOutOfRangeAreRefusedNamingTheFieldAndChangeNothing)
{
    Fixture f;
    const ViewState before = f.applied;
    ViewState edited = f.applied;
    edited.shadows.directional.atlasSize = 3000;
    edited.lights[0].intensity = 7.0f;
    const std::string error = applyViewState(edited, f.applied, f.scene);
    EXPECT_NE(error.find("directional.atlasSize"), std::string::npos) << error;
    EXPECT_EQ(f.applied.shadows.directional.atlasSize, before.shadows.directional.atlasSize);
    EXPECT_EQ(f.scene.lights[0].intensity, before.lights[0].intensity);
}

TEST(ViewStateTest, AZeroLightDirectionIsRefusedAndTheSceneKeepsItsLights)
{
    Fixture f;
    const glm::vec3 direction = f.scene.lights[2].direction;
    ViewState edited = f.applied;
    edited.lights[2].direction = glm::vec3(0.0f);
    const std::string error = applyViewState(edited, f.applied, f.scene);
    EXPECT_NE(error.find("direction"), std::string::npos) << error;
    EXPECT_EQ(f.scene.lights[2].direction, direction);
    EXPECT_EQ(f.applied.lights[2].direction, direction);
}

TEST(ViewStateTest, ShadowStrengthOutsideZeroToOneIsRefused)
{
    Fixture f;
    ViewState edited = f.applied;
    edited.lights[0].shadowStrength = 1.5f;
    EXPECT_NE(applyViewState(edited, f.applied, f.scene).find("shadowStrength"), std::string::npos);
}

} // namespace
} // namespace penumbra::viewer
