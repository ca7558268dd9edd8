// Spot and point shadows through the real drivers: front faces in the point faces, no light through walls,
// the tile budget and the global distance fade without directional lights.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/shadows/LocalLightProjection.hpp"

#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kLocalWidth = 640;
constexpr std::uint32_t kLocalHeight = 360;

class LocalShadowsTest : public GpuTest {
protected:
    render::FrameDesc frame() const
    {
        render::FrameDesc f;
        f.width = kLocalWidth;
        f.height = kLocalHeight;
        f.ambient.intensity = 0.0f;
        return f;
    }

    rhi::Image renderLit(const scene::Scene& scene, const render::FrameDesc& f)
    {
        return testing::renderLit(*device, scene, f);
    }
};

float maxLuminance(const rhi::Image& image)
{
    float m = 0.0f;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            m = std::max(m, luminance(image, x, y));
    return m;
}

render::FrameDesc inMode(render::FrameDesc frame, shadows::PointShadowMode mode)
{
    frame.shadows.local.pointMode = mode;
    return frame;
}

const char* modeName(shadows::PointShadowMode mode)
{
    return mode == shadows::PointShadowMode::Atlas ? "atlas" : "cube map";
}

TEST_F(LocalShadowsTest, PointFacesStoreTheLightFacingSideOfACaster)
{
    // Back-face culling with the RHI's winding keeps the crate's side facing the light: the depth stored
    // towards the crate's centre is the distance to its near face, not its far face (which an upside-down,
    // mirrored face would store: Unity renders point-light faces upside down and negates a view-matrix row to
    // undo it, as Catlike Coding's "Point and Spot Shadows" tutorial shows). Atlas
    // tiles use ordinary views; the cube map's mirrored views cull through rhi::cubeFaceCullMode.
    const scene::Scene scene = roomLitFromInside();
    const glm::vec3 light = scene.pointLights[0].position;
    const scene::Object& crate = scene.objects[*scene.findObject("crate")];
    const glm::vec3 centre = 0.5f * (crate.worldBounds.min + crate.worldBounds.max);
    const shadows::CubeFace face = shadows::cubeFace(centre - light);
    const glm::vec3 axis = shadows::cubeFaceAxis(face);
    for (const shadows::PointShadowMode mode : {shadows::PointShadowMode::Atlas, shadows::PointShadowMode::CubeMap}) {
        render::SceneRenderer renderer(*device, scene);
        renderer.render(scene.camera, inMode(frame(), mode));
        const shadows::LocalShadowPlan& plan = renderer.localPlan();
        const bool atlasMode = mode == shadows::PointShadowMode::Atlas;
        const std::uint32_t tile = static_cast<std::uint32_t>(plan.pointShadows[0]) + static_cast<std::uint32_t>(face);
        const shadows::LocalShadowView& view =
            atlasMode ? plan.tiles[tile].view : plan.cubes[0].faces[static_cast<std::size_t>(face)];
        const rhi::DepthImage depth =
            atlasMode ? rhi::readDepth(*device, renderer.localAtlas().texture())
                      : rhi::readDepth(*device, renderer.shadowCubes().texture(), rhi::cubeLayer(0, face));
        const glm::mat4 toTexture =
            atlasMode ? plan.tileData[tile].worldToAtlas : device->conventions().clipToTexture() * view.viewProjection;
        const glm::vec4 p = toTexture * glm::vec4(centre, 1.0f);
        const auto x = static_cast<std::uint32_t>(p.x / p.w * float(depth.width));
        const auto y = static_cast<std::uint32_t>(p.y / p.w * float(depth.height));
        const float stored =
            device->conventions().viewDepth(view.projection, depth.depth[std::size_t(y) * depth.width + x]);
        // Distances along the face axis to the crate's near and far faces.
        const float nearFace =
            std::min(glm::dot(crate.worldBounds.min - light, axis), glm::dot(crate.worldBounds.max - light, axis));
        const float farFace =
            std::max(glm::dot(crate.worldBounds.min - light, axis), glm::dot(crate.worldBounds.max - light, axis));
        std::printf("[ faces    ] %s %s: face %u stores %.4f towards the crate; near face %.4f, far face %.4f\n",
                    configuration().c_str(), modeName(mode), static_cast<unsigned>(face), stored, nearFace, farFace);
        EXPECT_NEAR(stored, nearFace, 0.02f) << modeName(mode);
    }
}

// local.depthBias, the constant depth bias beside the slope-scaled one, pushes the depths the atlas stores away from
// the light: the crate's near face stored with the design document's 50 000 lies behind the one stored without.
TEST_F(LocalShadowsTest, ConstantDepthBiasPushesStoredDepthsAwayFromTheLight)
{
    const scene::Scene scene = roomLitFromInside();
    const glm::vec3 light = scene.pointLights[0].position;
    const scene::Object& crate = scene.objects[*scene.findObject("crate")];
    const glm::vec3 centre = 0.5f * (crate.worldBounds.min + crate.worldBounds.max);
    const auto face = static_cast<std::uint32_t>(shadows::cubeFace(centre - light));
    render::FrameDesc f = frame();
    f.width = 160;
    f.height = 90;
    f.shadows.local.atlasSize = 512;
    const auto storedDistance = [&](float depthBias) {
        f.shadows.local.depthBias = depthBias;
        render::SceneRenderer renderer(*device, scene);
        renderer.render(scene.camera, f);
        const shadows::LocalShadowPlan& plan = renderer.localPlan();
        const std::uint32_t tile = static_cast<std::uint32_t>(plan.pointShadows[0]) + face;
        EXPECT_EQ(plan.tiles[tile].view.depthBias, depthBias);
        const rhi::DepthImage depth = rhi::readDepth(*device, renderer.localAtlas().texture());
        const glm::vec4 p = plan.tileData[tile].worldToAtlas * glm::vec4(centre, 1.0f);
        const auto x = static_cast<std::uint32_t>(p.x / p.w * float(depth.width));
        const auto y = static_cast<std::uint32_t>(p.y / p.w * float(depth.height));
        return device->conventions().viewDepth(plan.tiles[tile].view.projection,
                                               depth.depth[std::size_t(y) * depth.width + x]);
    };
    const float unbiased = storedDistance(0.0f);
    const float biased = storedDistance(50000.0f);
    std::printf("[ bias     ] %s: the crate's near face stored at %.5f, with a constant bias of 50000 at %.5f\n",
                configuration().c_str(), unbiased, biased);
    EXPECT_GT(biased, unbiased + 1e-4f);
    EXPECT_LT(biased, unbiased + 0.5f);
}

TEST_F(LocalShadowsTest, NoLightLeaksThroughAWallNextToAPointLight)
{
    // Only the light outside the +z wall: everything the camera sees is inside the room and in its shadow.
    scene::Scene scene = scenes::makePointLightRoomScene();
    scene.pointLights.erase(scene.pointLights.begin());
    const float leaked = maxLuminance(renderLit(scene, frame()));
    const float unshadowed = maxLuminance(renderLit(withoutShadows(scene), frame()));
    std::printf("[ leak     ] %s: brightest pixel %.1f with shadows, %.1f without\n", configuration().c_str(), leaked,
                unshadowed);
    EXPECT_GT(unshadowed, 100.0f) << "without shadows the light must reach into the room";
    EXPECT_LE(leaked, 1.0f) << "light leaks through the wall";
}

TEST_F(LocalShadowsTest, EveryLightGetsTilesWhileTheAtlasHasRoomAndTheRestAreReported)
{
    scene::Scene scene = scenes::makeMixedLightsScene();
    scene.pointLights.push_back({.name = "third bulb", .position = {4.0f, 2.0f, 6.0f}});
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, frame());
    // 3 spot tiles and 3 x 6 point faces: more than the 16 tiles the atlas once held.
    EXPECT_EQ(renderer.localPlan().tiles.size(), 21u);
    EXPECT_TRUE(renderer.localPlan().report.empty());
    for (const int first : renderer.localPlan().pointShadows)
        EXPECT_GE(first, 0);

    // 256^2 holds sixteen tiles of the 64-texel floor: the light of the lowest priority loses its shadow (never its
    // light) and is named with the reason.
    render::FrameDesc small = frame();
    small.shadows.local.atlasSize = 256;
    small.shadows.local.minTileResolution = 64;
    render::SceneRenderer crowded(*device, scene);
    const render::FrameStats stats = crowded.render(scene.camera, small);
    const std::string reason = "has no shadows: no shadow: the 256 x 256 local atlas has no room for its";
    const auto note = std::find_if(stats.notes.begin(), stats.notes.end(),
                                   [&](const std::string& n) { return n.find(reason) != std::string::npos; });
    ASSERT_NE(note, stats.notes.end());
    EXPECT_EQ(crowded.localPlan().report.size(), 1u);
    EXPECT_EQ(stats.shadowedLights + stats.lightsWithoutShadow,
              scene.lights.size() + scene.spotLights.size() + scene.pointLights.size());
}

TEST_F(LocalShadowsTest, DistanceFadeAppliesWithoutDirectionalLights)
{
    const scene::Scene scene = roomLitFromInside();
    ASSERT_TRUE(scene.lights.empty());
    render::FrameDesc near = frame();
    near.shadows.maxDistance = 0.5f; // everything in view is farther: no shadows at all
    const rhi::Image faded = renderLit(scene, near);
    const rhi::Image unshadowed = renderLit(withoutShadows(scene), near);
    const rhi::Image shadowed = renderLit(scene, frame());
    EXPECT_EQ(faded.bytes, unshadowed.bytes) << "shadows beyond the shadow distance";
    EXPECT_NE(shadowed.bytes, unshadowed.bytes) << "the room shows no shadows within the shadow distance";
}

} // namespace
} // namespace penumbra::testing
