// The shadow defaults of a frame without settings: the shadow distance reaches the scene's farthest point seen from
// the camera, within the camera's far plane.
#include "SceneShadowDefaults.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::apps {
namespace {

// A 2 m cube centred `distance` in front of a camera at the origin looking down -z.
scene::Scene cubeAhead(float distance, float farPlane = 200.0f)
{
    scene::Scene scene;
    scene.camera.farPlane = farPlane;
    const std::uint32_t material = scene.addMaterial({});
    scene.addObject("cube", scene.addMesh(scene::makeBox(glm::vec3(1.0f))), material,
                    glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -distance)));
    return scene;
}

TEST(SceneShadowDefaults, DistanceReachesTheFarthestCornerBeforeTheFade)
{
    // The cube's far face is 6 m away: the fade (the last 10%) starts there.
    EXPECT_FLOAT_EQ(sceneShadowDistance(cubeAhead(5.0f), 0.1f), 6.0f / 0.9f);
    const shadows::ShadowSettings settings = sceneShadowSettings(cubeAhead(5.0f));
    EXPECT_FLOAT_EQ(settings.maxDistance, 6.0f / 0.9f);
    EXPECT_EQ(settings.directional.atlasSize, 4096u);
    EXPECT_EQ(settings.local.atlasSize, 2048u);
    EXPECT_NO_THROW(shadows::validate(settings));
}

TEST(SceneShadowDefaults, DistanceStopsAtTheFarPlane)
{
    EXPECT_FLOAT_EQ(sceneShadowDistance(cubeAhead(50.0f, 20.0f), 0.1f), 20.0f);
}

TEST(SceneShadowDefaults, NothingAheadKeepsTheDocumentsDistance)
{
    EXPECT_EQ(sceneShadowDistance(scene::Scene{}, 0.1f), 0.0f);
    EXPECT_EQ(sceneShadowDistance(cubeAhead(-5.0f), 0.1f), 0.0f);
    EXPECT_EQ(sceneShadowSettings(cubeAhead(-5.0f)).maxDistance, shadows::ShadowSettings{}.maxDistance);
}

} // namespace
} // namespace penumbra::apps
