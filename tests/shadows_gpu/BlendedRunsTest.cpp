// Blended surfaces of one mesh in two materials, alternating in depth: instanced draws (FrameDesc::instancedDraws)
// batch only runs of neighbours in the back-to-front order (shadows::batchRuns), so the picture is that of a draw per
// object, byte for byte. Batched by mesh and material instead, every pane of one material would blend before every
// pane of the other, whatever lies in front.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"
#include "StaticShadowScenes.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/MeshGenerators.hpp"

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <string>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kBlendedWidth = 160;
constexpr std::uint32_t kBlendedHeight = 90;
// The panes' materials from the farthest to the nearest: runs of one and of two, so that batching by material
// moves panes past others of the other material.
constexpr const char* kPaneOrder = "rrbrbbrr";
constexpr std::uint32_t kPanes = 8;
constexpr std::uint32_t kRuns = 5; // rr | b | r | bb | rr

struct DrawnPanes {
    rhi::Image lit;
    render::FrameStats stats;
};

// Eight overlapping panes of one mesh standing one behind the other in front of the camera, red and blue as
// kPaneOrder says, over an opaque ground under a sun. The panes cast no shadow, so that only the lit pass's order
// of the blended draws shapes the picture. `blueBoundsTowardsCamera`: the blue panes' mesh is a copy whose bounds
// reach that far towards the camera (a box the mesh lies in, so nothing is culled): 16 moves their centres 8 nearer,
// between the nearest red pane and the camera, which sorts every blue pane after every red one and keeps their own
// order: the order of a batch per mesh and material.
scene::Scene alternatingPanes(float blueBoundsTowardsCamera = 0.0f)
{
    scene::Scene s;
    const std::uint32_t grey = s.addMaterial({.name = "grey", .baseColor = {0.6f, 0.6f, 0.6f, 1.0f}});
    const std::uint32_t red = s.addMaterial({.name = "red", .baseColor = {0.9f, 0.1f, 0.1f, 0.5f}, .blend = true});
    const std::uint32_t blue = s.addMaterial({.name = "blue", .baseColor = {0.1f, 0.2f, 0.9f, 0.5f}, .blend = true});
    s.addObject("ground", s.addMesh(scene::makeBox({10.0f, 0.1f, 10.0f})), grey,
                glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}));
    const std::uint32_t pane = s.addMesh(scene::makeBox({0.8f, 0.6f, 0.02f}));
    scene::MeshData reaching = s.meshes[pane];
    reaching.bounds.max.z += blueBoundsTowardsCamera;
    const std::uint32_t bluePane = blueBoundsTowardsCamera > 0.0f ? s.addMesh(std::move(reaching)) : pane;
    for (std::uint32_t i = 0; i < kPanes; ++i) {
        const bool isRed = kPaneOrder[i] == 'r';
        // Farthest first: pane i stands at z = -i, each a little to the right of the one behind.
        const glm::mat4 at = glm::translate(glm::mat4(1.0f), {0.25f * float(i), 0.8f, -float(kPanes - 1 - i)});
        const std::uint32_t object =
            s.addObject("pane " + std::to_string(i), isRed ? pane : bluePane, isRed ? red : blue, at);
        s.objects[object].castShadows = scene::ShadowCasting::Off;
    }
    s.lights = {{.name = "sun", .intensity = 2.0f, .direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.4f))}};
    s.camera = scene::lookAt({2.0f, 1.6f, 10.0f}, {0.9f, 0.8f, -3.5f}, 0.35f);
    s.validate();
    return s;
}

class BlendedRunsTest : public GpuTest {
protected:
    DrawnPanes draw(render::SceneRenderer& renderer, const scene::Scene& scene, bool instanced)
    {
        render::FrameDesc frame = litFrame(kBlendedWidth, kBlendedHeight, true, 1);
        frame.instancedDraws = instanced;
        DrawnPanes drawn;
        drawn.stats = renderer.render(scene.camera, frame);
        drawn.lit = rhi::readTexture(*device, renderer.litImage());
        return drawn;
    }

    DrawnPanes draw(const scene::Scene& scene, bool instanced)
    {
        render::SceneRenderer renderer(*device, scene);
        return draw(renderer, scene, instanced);
    }
};

TEST_F(BlendedRunsTest, AlternatingMaterialsBlendInBackToFrontRuns)
{
    const scene::Scene scene = alternatingPanes();
    render::SceneRenderer renderer(*device, scene);
    const DrawnPanes perObject = draw(renderer, scene, false);
    const DrawnPanes instanced = draw(renderer, scene, true);
    EXPECT_TRUE(perObject.lit.bytes == instanced.lit.bytes)
        << savePicture(perObject.lit, "blended-runs-per-object-" + configuration()) << " vs "
        << savePicture(instanced.lit, "blended-runs-instanced-" + configuration());
    EXPECT_EQ(perObject.stats.litDraws, 1 + kPanes);
    EXPECT_EQ(instanced.stats.litDraws, 1 + kRuns) << "the ground, then a draw per run of one material";
}

// The order of a batch per mesh and material (every red pane, then every blue one, each back to front), drawn with
// a draw per object from a scene whose blue panes sort nearer than every red one, against the right order: the
// comparison above must see it (measured: 925 of the 14 400 pixels on lavapipe).
TEST_F(BlendedRunsTest, BatchingByMaterialCatchesFault)
{
    const DrawnPanes right = draw(alternatingPanes(), false);
    const DrawnPanes batched = draw(alternatingPanes(16.0f), false);
    const std::size_t differing = differingPixels(right.lit, batched.lit, 1);
    std::printf("[ blended  ] batched by material: %zu of %u pixels differ\n", differing,
                kBlendedWidth * kBlendedHeight);
    EXPECT_GT(differing, std::size_t(kBlendedWidth * kBlendedHeight / 100))
        << savePicture(batched.lit, "blended-runs-batched-by-material-" + configuration());
}

} // namespace
} // namespace penumbra::testing
