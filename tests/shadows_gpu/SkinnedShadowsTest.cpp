// Skinned meshes posed on the GPU (render/src/skinning): the two-bone bend drawn at a pose the renderer was not made
// at gives the picture of its CPU-posed vertices, its shadow agrees with the ray cast of the posed mesh (and a caster
// pass left in the bind pose is caught), so do a walking figure's, and the local tile cache redraws exactly the lights
// that see the bend move.
#include "GltfAnimationScenes.hpp"
#include "GpuTesting.hpp"

#include "penumbra/gltf/GltfLoader.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/Posing.hpp"
#include "penumbra/truth/GroundTruth.hpp"
#include "penumbra/truth/ShadowTruth.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kSkinnedWidth = 160;
constexpr std::uint32_t kSkinnedHeight = 120;

scene::Scene loaded(const GltfBuilder& builder)
{
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("penumbra-skinned-" + std::to_string(::getpid()) + ".glb");
    builder.writeGlb(path);
    scene::Scene scene = gltf::loadGltf(path).scene;
    std::filesystem::remove(path);
    return scene;
}

scene::Scene bendScene() { return loaded(twoBoneBendScene()); }

// The bend's mesh drawn by a second node with a second skin over the same joints, whose inverse bind matrices move it
// 1 along +x first: one mesh in two poses.
scene::Scene twoSkinsOfOneMesh()
{
    GltfBuilder b = twoBoneBendScene();
    nlohmann::json& json = b.json();
    nlohmann::json skin = json["skins"][0];
    const std::array<float, 32> shifted{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0,  0, 1,
                                        1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, -1, 0, 1};
    skin["name"] = "shifted";
    skin["inverseBindMatrices"] = addFloatAccessor(b, shifted, "MAT4");
    json["skins"].push_back(skin);
    for (const nlohmann::json& node : json["nodes"])
        if (node.value("name", "") == "bar") {
            nlohmann::json copy = node;
            copy["name"] = "shifted bar";
            copy["skin"] = 1;
            b.addRoot(b.add("nodes", copy));
            break;
        }
    return loaded(b);
}

void pose(scene::Scene& scene, float time) { scene::poseScene(scene, scene::findAnimation(scene.rig, "bend"), time); }

// The bend with a spot light and a point light above the forearm, seen from above the forearm, whose shadows fall on
// the ground under it.
scene::Scene litBend()
{
    scene::Scene scene = bendScene();
    scene.spotLights = {{.name = "over",
                         .intensity = 20.0f,
                         .position = {-0.5f, 3.5f, 0.3f},
                         .direction = {0.0f, -1.0f, 0.0f},
                         .range = 8.0f,
                         .innerAngle = 0.5f,
                         .outerAngle = 0.6f}};
    scene.pointLights = {{.name = "bulb", .intensity = 10.0f, .position = {-0.5f, 3.0f, 0.4f}, .range = 8.0f}};
    scene.camera = scene::lookAt({-0.5f, 1.9f, 1.2f}, {-0.5f, 0.0f, 0.2f}, 0.9f);
    return scene;
}

class SkinnedShadowsTest : public GpuTest {
protected:
    // Each light's visibility view of `scene` posed by `animation` at `time`, drawn by a renderer made at the rest
    // pose, against the ray cast of the CPU-posed mesh.
    std::vector<truth::TruthComparison> againstTruth(scene::Scene scene, std::span<const scene::LightRef> lights,
                                                     const char* animation, float time, bool casterSkinning)
    {
        render::SceneRenderer renderer(*device, scene);
        renderer.setCasterSkinning(casterSkinning);
        scene::poseScene(scene, scene::findAnimation(scene.rig, animation), time);
        const truth::RayCaster cameraRays(scene, truth::RayKind::Camera);
        const truth::CpuGBuffer gbuffer =
            truth::traceGBuffer(scene, cameraRays, scene.camera, kSkinnedWidth, kSkinnedHeight);
        const truth::RayCaster shadowRays(scene);
        std::vector<truth::TruthComparison> comparisons;
        for (const scene::LightRef light : lights) {
            render::FrameDesc frame{.width = kSkinnedWidth, .height = kSkinnedHeight};
            frame.visibilityOf = light;
            renderer.render(scene.camera, frame);
            const rhi::Image view = rhi::readTexture(*device, renderer.visibilityImage());
            const truth::LightTruthTrace trace =
                truth::traceLightTruth(scene, shadowRays, gbuffer, renderer.planShadows(scene.camera, frame),
                                       frame.shadows, light);
            comparisons.push_back(
                truth::compareLightTruth(trace, shadowRays, gbuffer, truth::renderedVisibility(view)));
            const truth::TruthComparison& f = comparisons.back();
            std::printf("[ truth    ] %s %s at %g s of '%s', %s casters: lit %zu of %zu right, shadowed %zu of %zu "
                        "right\n",
                        configuration().c_str(), scene::lightKindName(light.kind), double(time), animation,
                        casterSkinning ? "skinned" : "bind-pose", f.lit.right, f.lit.compared, f.shadowed.right,
                        f.shadowed.compared);
        }
        return comparisons;
    }

    std::vector<truth::TruthComparison> bendAgainstTruth(bool casterSkinning)
    {
        return againstTruth(litBend(), kLights, "bend", 1.0f, casterSkinning);
    }

    static constexpr std::array<scene::LightRef, 3> kLights{scene::LightRef{scene::LightKind::Directional, 0},
                                                            scene::LightRef{scene::LightKind::Spot, 0},
                                                            scene::LightRef{scene::LightKind::Point, 0}};
};

// The renderer is made at the rest pose and the scene posed afterwards, as an application playing an animation does:
// only the GPU skinning can bring the bend into the picture, which must be the one of the same vertices posed on the
// CPU and uploaded as they are (a copy of the scene without its rig).
TEST_F(SkinnedShadowsTest, GpuSkinningDrawsTheCpuPose)
{
    scene::Scene scene = bendScene();
    render::SceneRenderer gpu(*device, scene);
    pose(scene, 1.0f);
    scene::Scene cpuPosed = scene;
    cpuPosed.rig = {};
    render::SceneRenderer cpu(*device, cpuPosed);
    const render::FrameDesc frame{.width = kSkinnedWidth, .height = kSkinnedHeight};
    gpu.render(scene.camera, frame);
    cpu.render(cpuPosed.camera, frame);
    const rhi::Image skinned = rhi::readTexture(*device, gpu.litImage());
    const rhi::Image reference = rhi::readTexture(*device, cpu.litImage());
    const std::size_t differing = differingPixels(skinned, reference, 0);
    std::printf("[ skinning ] %s: %zu of %u pixels differ between GPU and CPU skinning\n", configuration().c_str(),
                differing, kSkinnedWidth * kSkinnedHeight);
    // Rounding differs between the two (glm and the shader sum the joint matrices alike but fuse differently): an
    // edge pixel may flip, a bind-pose bar would differ in hundreds.
    EXPECT_LE(differing, 10u) << savePicture(skinned, "skinned-gpu-" + configuration()) << " vs "
                              << savePicture(reference, "skinned-cpu-" + configuration());
}

TEST_F(SkinnedShadowsTest, TheBentShadowsAgreeWithTheRayCast)
{
    for (const truth::TruthComparison& f : bendAgainstTruth(true)) {
        EXPECT_GT(f.shadowed.compared, 50u)
            << "the forearm's shadow, away from edges (measured: sun 67, spot 511, point 523 pixels)";
        EXPECT_GE(f.lit.share(), 0.995);
        EXPECT_GE(f.shadowed.share(), 0.995);
    }
}

// The caster passes drawn from the bind-pose vertices (the other passes posed): the bar stands upright in the shadow
// maps of every light, so the bent arm's shadow is missing where the ray cast finds it.
TEST_F(SkinnedShadowsTest, BindPoseCastersCatchesFault)
{
    for (const truth::TruthComparison& f : bendAgainstTruth(false)) {
        EXPECT_GT(f.shadowed.compared, 50u);
        EXPECT_LT(f.shadowed.share(), 0.9) << "measured: sun 0 of 67, spot 2 of 511, point 5 of 523";
    }
}

// The walking figure of eleven joints (tests/support/WalkingCharacterScene.cpp) mid-stride, the legs apart and one
// knee bent: the sun's and the spot light's shadows of the posed figure agree with the ray cast.
TEST_F(SkinnedShadowsTest, TheWalkingCharactersShadowsAgreeWithTheRayCast)
{
    scene::Scene scene = loaded(walkingCharacterScene());
    // From the figure's left, above its shadows, which fall to its right and back.
    scene.camera = scene::lookAt({-0.8f, 4.0f, 1.8f}, {-0.9f, 0.0f, -0.8f}, 0.9f);
    constexpr std::array<scene::LightRef, 2> lights{scene::LightRef{scene::LightKind::Directional, 0},
                                                    scene::LightRef{scene::LightKind::Spot, 0}};
    for (const truth::TruthComparison& f : againstTruth(std::move(scene), lights, "walk", 0.3f, true)) {
        EXPECT_GT(f.shadowed.compared, 100u) << "the figure's shadow, away from edges (measured: sun 120, spot 521)";
        EXPECT_GE(f.lit.share(), 0.995);
        EXPECT_GE(f.shadowed.share(), 0.995);
    }
}

// Objects of one mesh and material are drawn as the instances of one draw; two skins posing one glTF mesh must not be
// (each skinned object has a mesh of its own): the instanced frame draws each bar apart, as a draw per object does.
TEST_F(SkinnedShadowsTest, TwoPosesOfOneMeshAreNotDrawnAsOne)
{
    scene::Scene scene = twoSkinsOfOneMesh();
    ASSERT_EQ(scene.rig.deformers.size(), 2u);
    render::SceneRenderer renderer(*device, scene);
    pose(scene, 1.0f);
    render::FrameDesc frame{.width = kSkinnedWidth, .height = kSkinnedHeight};
    const render::FrameStats instanced = renderer.render(scene.camera, frame);
    const rhi::Image instancedPicture = rhi::readTexture(*device, renderer.litImage());
    frame.instancedDraws = false;
    const render::FrameStats perObject = renderer.render(scene.camera, frame);
    EXPECT_EQ(instanced.litDraws, 3u) << "the ground and each bar";
    EXPECT_EQ(instanced.litDraws, perObject.litDraws);
    EXPECT_EQ(differingPixels(instancedPicture, rhi::readTexture(*device, renderer.litImage()), 0), 0u);
}

// A deformed mesh drawn by a second object as well would put both in one pose: refused, naming the object.
TEST_F(SkinnedShadowsTest, ADeformedMeshSharedWithAnotherObjectIsRefused)
{
    scene::Scene scene = bendScene();
    const scene::Object bar = scene.objects.at(scene.rig.deformers.at(0).object);
    scene.addObject("copy", bar.mesh, bar.material, glm::mat4(1.0f));
    try {
        render::SceneRenderer renderer(*device, scene);
        FAIL() << "no error";
    } catch (const scene::SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("is drawn by 2 objects"), std::string::npos) << e.what();
    }
}

// Posing a skinned mesh keeps its model matrix (its joints place it) and its vertex buffer: the tile cache must see
// the pose itself. A spot light over the bar draws again when the bar bends, one looking elsewhere keeps its tile.
TEST_F(SkinnedShadowsTest, BendingRedrawsOnlyTheSpotLightThatSeesIt)
{
    scene::Scene scene = bendScene();
    const auto spot = [](const char* name, float x, float z) {
        return scene::SpotLight{.name = name,
                                .intensity = 20.0f,
                                .position = {x, 4.0f, z},
                                .direction = {0.0f, -1.0f, 0.0f},
                                .range = 8.0f,
                                .innerAngle = 0.3f,
                                .outerAngle = 0.4f};
    };
    // "elsewhere" lights the ground beside the bar, in view, but its cone misses the bar at every pose.
    scene.spotLights = {spot("over", 0.0f, 0.0f), spot("elsewhere", 2.2f, -1.5f)};
    render::SceneRenderer renderer(*device, scene);
    const render::FrameDesc frame{.width = kSkinnedWidth, .height = kSkinnedHeight};
    EXPECT_EQ(renderer.render(scene.camera, frame).localTilesDrawn, 2u);
    EXPECT_EQ(renderer.render(scene.camera, frame).localTilesCached, 2u);
    pose(scene, 0.5f);
    const render::FrameStats bent = renderer.render(scene.camera, frame);
    EXPECT_EQ(bent.localTilesDrawn, 1u);
    EXPECT_EQ(bent.localTilesCached, 1u);
    ASSERT_EQ(bent.localShadowUpdates.size(), 1u);
    EXPECT_EQ(bent.localShadowUpdates[0], "spot light 0 ('over'): a caster in its view changed");
}

} // namespace
} // namespace penumbra::testing
