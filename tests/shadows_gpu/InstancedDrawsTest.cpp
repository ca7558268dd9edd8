// Instanced draws (FrameDesc::instancedDraws): objects that share a mesh and material are drawn as the instances of
// one draw in the depth prepass, the lit pass and every shadow view, and the pictures are those of a draw per object,
// byte for byte: the lit image and both atlases, with cubes, alpha-tested double-sided cards and blended panes
// repeated, a sun, a spot and a point light, receiver-side and caster-side normal offset.
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

constexpr std::uint32_t kInstancedWidth = 320;
constexpr std::uint32_t kInstancedHeight = 180;
constexpr std::uint32_t kCubes = 400;
constexpr std::uint32_t kCards = 12;
constexpr std::uint32_t kInstancedPanes = 6;

// The cube grid with a row of double-sided clip cards (the checker of material.glsl cuts them) and blended panes,
// each row one mesh and one material, and a spot and a point light among them.
scene::Scene repeatedScene(scene::NormalBiasSide side)
{
    scene::Scene scene = scenes::makeCubeGridScene(kCubes);
    const std::uint32_t card = scene.addMesh(scene::makePlane(0.7f));
    const std::uint32_t cards = scene.addMaterial({.name = "cards",
                                                   .baseColor = {0.3f, 0.6f, 0.3f, 1.0f},
                                                   .caster = scene::CasterMode::Clip,
                                                   .doubleSided = true});
    const std::uint32_t pane = scene.addMesh(scene::makeBox({0.5f, 0.5f, 0.05f}));
    const std::uint32_t glass =
        scene.addMaterial({.name = "glass", .baseColor = {0.4f, 0.5f, 0.9f, 0.5f}, .blend = true});
    const float edge = 0.5f * scenes::kCubeGridPitch * 20.0f;
    for (std::uint32_t i = 0; i < kCards; ++i) {
        // Stood upright, each turned a little further about y.
        const glm::mat4 placed =
            glm::rotate(glm::translate(glm::mat4(1.0f), {-8.0f + 1.4f * float(i), 1.2f, edge - 6.0f}), 0.3f * float(i),
                        glm::vec3(0, 1, 0));
        scene.addObject("card " + std::to_string(i), card, cards,
                        glm::rotate(placed, glm::radians(90.0f), glm::vec3(1, 0, 0)));
    }
    for (std::uint32_t i = 0; i < kInstancedPanes; ++i)
        scene.addObject("pane " + std::to_string(i), pane, glass,
                        glm::translate(glm::mat4(1.0f), {-5.0f + 2.0f * float(i), 0.8f, edge - 3.0f}));
    scene.spotLights = {{.name = "spot",
                         .intensity = 6.0f,
                         .position = {2.0f, 6.0f, edge - 4.0f},
                         .direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.6f)),
                         .range = 20.0f}};
    scene.pointLights = {{.name = "lamp", .intensity = 4.0f, .position = {-4.0f, 2.5f, edge - 9.0f}, .range = 10.0f}};
    scene.lights[0].normalBiasSide = side;
    scene.spotLights[0].normalBiasSide = side;
    scene.pointLights[0].normalBiasSide = side;
    scene.validate();
    return scene;
}

struct DrawnBatches {
    rhi::Image lit;
    rhi::DepthImage directional;
    rhi::DepthImage local;
    render::FrameStats stats;
};

class InstancedDrawsTest : public GpuTest {
protected:
    DrawnBatches draw(const scene::Scene& scene, bool instanced)
    {
        render::FrameDesc frame = litFrame(kInstancedWidth, kInstancedHeight, true, 1);
        frame.instancedDraws = instanced;
        frame.shadows.directional.atlasSize = 1024;
        frame.shadows.local.atlasSize = 1024;
        render::SceneRenderer renderer(*device, scene);
        DrawnBatches drawn;
        drawn.stats = renderer.render(scene.camera, frame);
        drawn.lit = rhi::readTexture(*device, renderer.litImage());
        drawn.directional = rhi::readDepth(*device, renderer.atlas().texture());
        drawn.local = rhi::readDepth(*device, renderer.localAtlas().texture());
        return drawn;
    }

    void expectSamePictures(scene::NormalBiasSide side, const char* name)
    {
        const scene::Scene scene = repeatedScene(side);
        const DrawnBatches perObject = draw(scene, false);
        const DrawnBatches instanced = draw(scene, true);
        EXPECT_TRUE(perObject.lit.bytes == instanced.lit.bytes) << name << ": the lit images differ";
        EXPECT_TRUE(perObject.directional.depth == instanced.directional.depth)
            << name << ": the directional atlases differ";
        EXPECT_TRUE(perObject.local.depth == instanced.local.depth) << name << ": the local atlases differ";
        savePicture(instanced.lit, std::string("instanced-draws-") + name + "-" + configuration());

        // Ground, cubes, cards, panes: one draw each; the panes are one run, nearest last.
        EXPECT_EQ(instanced.stats.litDraws, 4u) << name;
        EXPECT_EQ(instanced.stats.depthPrepassDraws, 3u) << name; // blended panes are not in the prepass
        // A draw per object in view (the grid reaches out of it: ViewCullingTest), against the four groups' draws.
        EXPECT_GT(perObject.stats.litDraws, 50 * instanced.stats.litDraws) << name;
        EXPECT_LT(perObject.stats.litDraws, 1 + kCubes + kCards + kInstancedPanes) << name;
        // Every shadow view draws each of the four meshes at most once.
        const std::uint32_t cascades = 4, localViews = 1 + 6;
        EXPECT_LE(instanced.stats.casterDraws, 4 * cascades) << name;
        EXPECT_LE(instanced.stats.localCasterDraws, 4 * localViews) << name;
        EXPECT_GT(perObject.stats.casterDraws, 10 * instanced.stats.casterDraws) << name;
    }
};

TEST_F(InstancedDrawsTest, PicturesMatchADrawPerObject)
{
    expectSamePictures(scene::NormalBiasSide::Receiver, "receiver-side");
}

TEST_F(InstancedDrawsTest, PicturesMatchADrawPerObjectWithCasterSideNormalOffset)
{
    expectSamePictures(scene::NormalBiasSide::Caster, "caster-side");
}

} // namespace
} // namespace penumbra::testing
