// Shadow casters culled on the GPU (ShadowSettings::culling gpu, shaders/caster_culling.comp): the culling pass's
// per-tile lists are the planner's (casterInVolume) and the pictures and both atlases are those of CPU culling, byte
// for byte, on a small grid of instanced cubes that reaches out of the cascades, with a sun and a spot light.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scene/ViewFrustum.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/shadows/GpuCasterCulling.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/LocalShadowPass.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kCulledCubes = 144;

scene::Scene culledScene()
{
    scene::Scene scene = scenes::makeCubeGridScene(kCulledCubes);
    scene.spotLights = {{.name = "spot",
                         .intensity = 6.0f,
                         .position = {0.0f, 6.0f, 2.0f},
                         .direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.5f)),
                         .range = 12.0f}};
    scene.validate();
    return scene;
}

render::FrameDesc smallFrame(shadows::CasterCullingMode culling)
{
    render::FrameDesc frame = litFrame(160, 90, false, 1);
    frame.instancedDraws = true;
    frame.shadows.culling = culling;
    frame.shadows.directional.atlasSize = 512;
    frame.shadows.local.atlasSize = 512;
    return frame;
}

class GpuCullingTest : public GpuTest {
protected:
    // The planner's list of every realtime tile (cascades, then local tiles) and the GPU's for the same volumes;
    // `fault` changes what the GPU is given before it culls; `tilesPerDispatch` splits the tiles over dispatches and
    // `chunkRuns` the lists over workgroups.
    template <typename Fault>
    void cullBoth(Fault fault, std::vector<std::vector<std::uint32_t>>& planned,
                  std::vector<std::vector<std::uint32_t>>& culled,
                  std::uint32_t tilesPerDispatch = std::numeric_limits<std::uint32_t>::max(),
                  const scene::Scene& scene = culledScene(), std::uint32_t chunkRuns = shadows::kCullingChunkRuns)
    {
        render::SceneRenderer renderer(*device, scene);
        const render::ShadowPlans plans =
            renderer.planShadows(scene.camera, smallFrame(shadows::CasterCullingMode::Cpu));
        std::vector<shadows::CasterVolume> volumes;
        for (const std::vector<shadows::ShadowTileDraw>& tiles :
             {shadows::DirectionalShadowPass::tileDraws(plans.directional),
              shadows::LocalShadowPass::tileDraws(plans.local)})
            for (const shadows::ShadowTileDraw& tile : tiles) {
                planned.push_back(tile.casters);
                volumes.push_back(tile.volume);
            }
        const std::vector<shadows::ShadowCaster>& casters = renderer.gpuScene().casters();
        std::vector<shadows::Bounds> bounds = renderer.gpuScene().casterBounds();
        fault(volumes, bounds);
        shadows::GpuCasterCulling culling(*device, tilesPerDispatch, chunkRuns);
        auto commands = device->createCommandList();
        culling.record(*commands, casters, bounds, volumes);
        device->submit(*commands);
        culled = culling.readLists();
    }

    struct Drawn {
        rhi::Image lit;
        rhi::DepthImage directional;
        rhi::DepthImage local;
        render::FrameStats stats;
    };

    // A cube of the first cascade moved far out of every tile between two records into the same resident storage:
    // what each record uploaded, and the moved record's lists beside those of a culling that uploads everything.
    // `reported`: the record sees the scene's change log; otherwise a copy taken before the move, which misses it.
    struct MovedCaster {
        std::vector<shadows::CasterRange> first, unchanged, moved;
        std::uint32_t caster = 0;
        shadows::Bounds bounds; // the moved caster's in GpuScene::casterBounds
        glm::vec3 movedMin{0.0f};
        std::vector<std::vector<std::uint32_t>> resident, full;
    };
    MovedCaster moveCaster(bool reported)
    {
        scene::Scene scene = culledScene();
        render::SceneRenderer renderer(*device, scene);
        const render::FrameDesc frame = smallFrame(shadows::CasterCullingMode::Gpu);
        const render::GpuScene& gpuScene = renderer.gpuScene();
        shadows::GpuCasterCulling culling(*device);
        const auto record = [&](shadows::GpuCasterCulling& target, const shadows::CasterChanges* changes) {
            const render::ShadowPlans plans = renderer.planShadows(scene.camera, frame);
            std::vector<shadows::CasterVolume> volumes;
            for (const shadows::ShadowTileDraw& tile : shadows::DirectionalShadowPass::tileDraws(plans.directional))
                volumes.push_back(tile.volume);
            auto commands = device->createCommandList();
            target.record(*commands, gpuScene.casters(), gpuScene.casterBounds(), volumes, changes);
            device->submit(*commands);
        };
        MovedCaster result;
        record(culling, &gpuScene.casterChanges());
        result.first = culling.uploaded();
        result.caster = culling.readLists().front().back();
        record(culling, &gpuScene.casterChanges());
        result.unchanged = culling.uploaded();
        const shadows::CasterChanges beforeMove = gpuScene.casterChanges();
        // The ground is object and caster 0, cube i object and caster i.
        scene::Object& object = scene.objects.at(result.caster);
        object.transform = glm::translate(glm::mat4(1.0f), glm::vec3(500.0f, 0.5f, 500.0f));
        object.worldBounds = scene.meshOf(object).bounds.transformed(object.transform);
        ++scene.revision;
        result.movedMin = object.worldBounds.min;
        record(culling, reported ? &gpuScene.casterChanges() : &beforeMove);
        result.moved = culling.uploaded();
        result.bounds = gpuScene.casterBounds().at(result.caster);
        result.resident = culling.readLists();
        shadows::GpuCasterCulling fresh(*device);
        record(fresh, nullptr);
        result.full = fresh.readLists();
        return result;
    }

    Drawn draw(shadows::CasterCullingMode culling)
    {
        const scene::Scene scene = culledScene();
        render::SceneRenderer renderer(*device, scene);
        Drawn drawn;
        drawn.stats = renderer.render(scene.camera, smallFrame(culling));
        drawn.lit = rhi::readTexture(*device, renderer.litImage());
        drawn.directional = rhi::readDepth(*device, renderer.atlas().texture());
        drawn.local = rhi::readDepth(*device, renderer.localAtlas().texture());
        return drawn;
    }

    // A cube (object `index`; the last one by default) lifted into the near view: `reported` raises the scene's
    // revision, as an editor must.
    static void liftCube(scene::Scene& scene, bool reported, std::size_t index = kCulledCubes)
    {
        scene::Object& cube = scene.objects.at(index);
        cube.transform = glm::translate(glm::mat4(1.0f), scene.camera.position + glm::vec3(0.0f, -1.0f, -4.0f));
        cube.worldBounds = scene.meshOf(cube).bounds.transformed(cube.transform);
        if (reported)
            ++scene.revision;
    }
};

TEST_F(GpuCullingTest, ListsMatchThePlanner)
{
    std::vector<std::vector<std::uint32_t>> planned, culled;
    cullBoth([](auto&, auto&) {}, planned, culled);
    ASSERT_EQ(planned.size(), 5u) << "four cascades and the spot light's tile";
    // In the planner's order too: the ground is caster 0 and the cubes share one batch, so the batches' order is
    // ascending, as the planner's lists are.
    EXPECT_EQ(culled, planned);
    // Some cubes lie out of every tile's reach, and the culling bias leaves some out of the later cascades.
    EXPECT_LT(planned.back().size(), kCulledCubes);
    EXPECT_LT(planned[3].size(), kCulledCubes);
    // The same lists where the tiles are culled two per dispatch, as a device with a short storage range culls 10^6
    // casters.
    std::vector<std::vector<std::uint32_t>> replanned, split;
    cullBoth([](auto&, auto&) {}, replanned, split, 2);
    EXPECT_EQ(split, planned);
}

// Lists longer than a workgroup's chunk of places are laid out by a workgroup per chunk, each counting the marks
// before it: 5 000 cubes and then 300 spheres, a chunk of 2 048 places each, so that the cubes' batch runs through
// three chunks and the spheres' begins inside the last.
TEST_F(GpuCullingTest, ListsMatchThePlannerInChunks)
{
    constexpr std::uint32_t kCubes = 5000, kSpheres = 300;
    scene::Scene scene = scenes::makeCubeGridScene(kCubes);
    const std::uint32_t sphere = scene.addMesh(scene::makeSphere(0.4f, 8, 4));
    // In rows before the camera, over the cubes.
    const glm::vec3 eye = scene.camera.position;
    for (std::uint32_t i = 0; i < kSpheres; ++i)
        scene.addObject("sphere " + std::to_string(i), sphere, 0,
                        glm::translate(glm::mat4(1.0f),
                                       eye + glm::vec3(float(i % 20) - 10.0f, -1.5f, -6.0f - float(i / 20))));
    scene.validate();
    std::vector<std::vector<std::uint32_t>> planned, culled;
    cullBoth([](auto&, auto&) {}, planned, culled, std::numeric_limits<std::uint32_t>::max(), scene, 1);
    ASSERT_GT(scene.objects.size(), 2 * shadows::kCullingRunPlaces);
    EXPECT_EQ(culled, planned);
    // The spheres cast in the first cascade, and the cubes' list reaches past the first chunk.
    EXPECT_GT(std::count_if(planned[0].begin(), planned[0].end(), [](std::uint32_t c) { return c > kCubes; }), 0);
    EXPECT_GT(std::count_if(planned[0].begin(), planned[0].end(),
                            [](std::uint32_t c) { return c > shadows::kCullingRunPlaces && c <= kCubes; }),
              0);
}

// The camera's view as a volume (the lit objects' culling, GpuViewCulling): the GPU keeps the boxes the CPU's
// casterInVolume and the lit draws' scene::ViewFrustum keep, and the 16:9 view keeps cubes at its sides that a square
// one of the same height does not.
TEST_F(GpuCullingTest, CameraViewListsMatchTheCpu)
{
    const scene::Scene scene = culledScene();
    render::SceneRenderer renderer(*device, scene);
    const scene::Camera& camera = scene.camera;
    const float aspect = 16.0f / 9.0f;
    const std::vector<shadows::CasterVolume> volumes{shadows::frustumVolume(camera.view(), camera.fovY, aspect,
                                                                            camera.nearPlane, camera.farPlane),
                                                     shadows::frustumVolume(camera.view(), camera.fovY, 1.0f,
                                                                            camera.nearPlane, camera.farPlane)};
    const std::vector<shadows::ShadowCaster>& casters = renderer.gpuScene().casters();
    const std::vector<shadows::Bounds>& bounds = renderer.gpuScene().casterBounds();
    shadows::GpuCasterCulling culling(*device);
    auto commands = device->createCommandList();
    culling.record(*commands, casters, bounds, volumes);
    device->submit(*commands);
    const std::vector<std::vector<std::uint32_t>> culled = culling.readLists();
    const scene::ViewFrustum frustum(camera, aspect);
    std::vector<std::vector<std::uint32_t>> expected(2);
    std::vector<std::uint32_t> shown;
    for (std::uint32_t i = 0; i < bounds.size(); ++i) {
        for (std::size_t v = 0; v < volumes.size(); ++v)
            if (shadows::casterInVolume(bounds[i], volumes[v]))
                expected[v].push_back(i);
        if (frustum.mayShow({bounds[i].min, bounds[i].max}))
            shown.push_back(i);
    }
    EXPECT_EQ(culled, expected);
    EXPECT_EQ(culled[0], shown);
    EXPECT_GT(culled[0].size(), culled[1].size());
    EXPECT_LT(culled[0].size(), bounds.size()) << "some cubes lie out of view";
}

// The comparison sees a caster dropped (its box moved far away) and a wrong bounds test (a cascade's square shrunk).
TEST_F(GpuCullingTest, DroppedCasterCatchesFault)
{
    std::vector<std::vector<std::uint32_t>> planned, culled;
    cullBoth(
        [](auto&, std::vector<shadows::Bounds>& bounds) {
            bounds[kCulledCubes / 2] = {glm::vec3(1e6f), glm::vec3(1e6f)};
        },
        planned, culled);
    EXPECT_NE(culled, planned);
}

TEST_F(GpuCullingTest, WrongBoundsTestCatchesFault)
{
    std::vector<std::vector<std::uint32_t>> planned, culled;
    cullBoth([](std::vector<shadows::CasterVolume>& volumes, auto&) { volumes[0].square.z *= 0.5f; }, planned, culled);
    EXPECT_NE(culled, planned);
}

TEST_F(GpuCullingTest, PicturesMatchCpuCulling)
{
    const Drawn cpu = draw(shadows::CasterCullingMode::Cpu);
    const Drawn gpu = draw(shadows::CasterCullingMode::Gpu);
    EXPECT_TRUE(cpu.lit.bytes == gpu.lit.bytes)
        << "the lit images differ: " << savePicture(cpu.lit, "gpu-culling-cpu-" + configuration()) << " "
        << savePicture(gpu.lit, "gpu-culling-gpu-" + configuration());
    EXPECT_TRUE(cpu.directional.depth == gpu.directional.depth) << "the directional atlases differ";
    EXPECT_TRUE(cpu.local.depth == gpu.local.depth) << "the local atlases differ";
    EXPECT_GT(gpu.stats.casterDraws, 0u);
}

// The lit objects stay resident with GPU culling, culled against the view on the GPU
// (render/src/passes/GpuViewCulling): after a cube moved the next frame is still CPU culling's, byte for byte. A
// shadows-only cube ahead of it makes the view's list places differ from the objects' indices, which the moved
// object's upload translates (where it took the object's index, another cube would move).
TEST_F(GpuCullingTest, MovedObjectMatchesCpuCulling)
{
    scene::Scene scene = culledScene();
    scene.objects.at(1).castShadows = scene::ShadowCasting::ShadowsOnly;
    const render::FrameDesc frame = smallFrame(shadows::CasterCullingMode::Gpu);
    render::SceneRenderer gpu(*device, scene);
    gpu.render(scene.camera, frame);
    const rhi::Image before = rhi::readTexture(*device, gpu.litImage());
    liftCube(scene, true, kCulledCubes / 2);
    gpu.render(scene.camera, frame);
    const rhi::Image moved = rhi::readTexture(*device, gpu.litImage());
    render::SceneRenderer cpu(*device, scene);
    cpu.render(scene.camera, smallFrame(shadows::CasterCullingMode::Cpu));
    const rhi::Image reference = rhi::readTexture(*device, cpu.litImage());
    EXPECT_FALSE(before.bytes == moved.bytes) << "the cube moved into view";
    EXPECT_TRUE(moved.bytes == reference.bytes)
        << "the lit images differ: " << savePicture(reference, "gpu-culling-moved-cpu-" + configuration()) << " "
        << savePicture(moved, "gpu-culling-moved-gpu-" + configuration());
}

// A move whose editor does not raise Scene::revision is found by the renderer's spot checks, not drawn stale.
TEST_F(GpuCullingTest, UnreportedEditCatchesFault)
{
    scene::Scene scene = culledScene();
    const render::FrameDesc frame = smallFrame(shadows::CasterCullingMode::Gpu);
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, frame);
    liftCube(scene, false);
    EXPECT_THROW(renderer.render(scene.camera, frame), rhi::Error);
}

// Instances stay in GPU storage: the first record uploads every caster, one with nothing changed none, one after a
// cube moved that cube alone, and the lists are those of a full upload.
TEST_F(GpuCullingTest, MovedCasterIsUploadedAlone)
{
    const MovedCaster moved = moveCaster(true);
    ASSERT_EQ(moved.first.size(), 1u);
    EXPECT_EQ(moved.first[0].first, 0u);
    EXPECT_EQ(moved.first[0].count, kCulledCubes + 1) << "the ground and every cube";
    EXPECT_TRUE(moved.unchanged.empty());
    EXPECT_EQ(moved.moved, (std::vector<shadows::CasterRange>{{moved.caster, 1}}));
    EXPECT_EQ(moved.bounds.min, moved.movedMin);
    EXPECT_EQ(moved.resident, moved.full);
    EXPECT_NE(moved.full.front(), std::vector<std::uint32_t>()) << "the first cascade keeps other casters";
}

// A record that misses the move (a change log from before it) keeps the stale box: its lists still hold the cube.
TEST_F(GpuCullingTest, UnreportedMoveCatchesFault)
{
    const MovedCaster moved = moveCaster(false);
    EXPECT_TRUE(moved.moved.empty());
    EXPECT_NE(moved.resident, moved.full);
}

} // namespace
} // namespace penumbra::testing
