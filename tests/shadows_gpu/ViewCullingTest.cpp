// Objects outside the camera's view are not drawn by the depth prepass and the lit pass (render/passes/LitDraws):
// the picture is the one with those objects removed, byte for byte, and the draws are those of the objects in view;
// an object that reaches into the view from outside is still drawn.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kCullingWidth = 320;
constexpr std::uint32_t kCullingHeight = 180;

struct DrawnCulled {
    rhi::Image lit;
    render::FrameStats stats;
};

class ViewCullingTest : public GpuTest {
protected:
    DrawnCulled draw(const scene::Scene& scene)
    {
        render::FrameDesc frame = litFrame(kCullingWidth, kCullingHeight, true, 1);
        frame.instancedDraws = false; // a draw per object: the draws count the objects drawn
        render::SceneRenderer renderer(*device, scene);
        DrawnCulled drawn;
        drawn.stats = renderer.render(scene.camera, frame);
        drawn.lit = rhi::readTexture(*device, renderer.litImage());
        return drawn;
    }
};

// Cubes that cast no shadow (so the atlases are those of the plain scene) behind the camera, beyond its far plane,
// and to each side of its view.
void addCubesOutOfView(scene::Scene& scene, std::uint32_t mesh, std::uint32_t material)
{
    const scene::Camera& camera = scene.camera;
    const glm::vec3 right = camera.right();
    const glm::vec3 up = glm::cross(right, camera.forward);
    const float farther = camera.farPlane + 5.0f;
    const std::vector<glm::vec3> places = {camera.position - 3.0f * camera.forward,
                                           camera.position - 20.0f * camera.forward,
                                           camera.position + farther * camera.forward,
                                           camera.position + 10.0f * camera.forward + 40.0f * right,
                                           camera.position + 10.0f * camera.forward - 40.0f * right,
                                           camera.position + 10.0f * camera.forward + 40.0f * up,
                                           camera.position + 10.0f * camera.forward - 40.0f * up};
    for (std::size_t i = 0; i < places.size(); ++i) {
        const std::uint32_t object = scene.addObject("out of view " + std::to_string(i), mesh, material,
                                                     glm::translate(glm::mat4(1.0f), places[i]));
        scene.objects[object].castShadows = scene::ShadowCasting::Off;
    }
}

TEST_F(ViewCullingTest, ObjectsOutOfViewAreNotDrawnAndChangeNothing)
{
    const scene::Scene plain = scenes::makeShadowTestScene();
    scene::Scene crowded = plain;
    const std::uint32_t cube = crowded.addMesh(scene::makeBox({0.5f, 0.5f, 0.5f}));
    const std::uint32_t red = crowded.addMaterial({.name = "red", .baseColor = {0.9f, 0.1f, 0.1f, 1.0f}});
    addCubesOutOfView(crowded, cube, red);
    crowded.validate();
    const DrawnCulled expected = draw(plain);
    const DrawnCulled drawn = draw(crowded);
    EXPECT_EQ(drawn.stats.litDraws, expected.stats.litDraws);
    EXPECT_EQ(drawn.stats.depthPrepassDraws, expected.stats.depthPrepassDraws);
    EXPECT_TRUE(drawn.lit.bytes == expected.lit.bytes) << "objects out of view changed the picture";
}

TEST_F(ViewCullingTest, AnObjectReachingIntoTheViewIsDrawn)
{
    scene::Scene scene = scenes::makeShadowTestScene();
    const DrawnCulled expected = draw(scene);
    // A long bar whose centre lies far to the right of the view, its left end across the middle of the picture.
    const scene::Camera& camera = scene.camera;
    const std::uint32_t bar = scene.addMesh(scene::makeBox({40.0f, 0.2f, 0.2f}));
    const std::uint32_t red = scene.addMaterial({.name = "red", .baseColor = {0.9f, 0.1f, 0.1f, 1.0f}});
    const std::uint32_t object =
        scene.addObject("bar", bar, red,
                        glm::translate(glm::mat4(1.0f),
                                       camera.position + 8.0f * camera.forward + 40.0f * camera.right()));
    scene.objects[object].castShadows = scene::ShadowCasting::Off;
    scene.validate();
    const DrawnCulled drawn = draw(scene);
    EXPECT_EQ(drawn.stats.litDraws, expected.stats.litDraws + 1);
    EXPECT_FALSE(drawn.lit.bytes == expected.lit.bytes) << "the bar is not in the picture";
}

} // namespace
} // namespace penumbra::testing
