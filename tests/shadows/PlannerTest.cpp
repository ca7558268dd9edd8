#include "ShadowTestSupport.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/TentFilter.hpp"

#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

ShadowCamera streetCamera()
{
    ShadowCamera camera = testing::uprightCamera(glm::vec3(2.0f, 1.7f, 5.0f), glm::vec3(0.2f, -0.1f, -1.0f));
    camera.fovY = 1.0f;
    camera.aspect = 16.0f / 9.0f;
    camera.nearPlane = 0.1f;
    camera.farPlane = 300.0f;
    return camera;
}

std::vector<DirectionalShadowLightInput> sixLights()
{
    std::vector<DirectionalShadowLightInput> lights(6);
    for (std::size_t i = 0; i < lights.size(); ++i)
        lights[i].direction = glm::normalize(glm::vec3(0.1f * static_cast<float>(i), -1.0f, 0.3f));
    lights[1].strength = 0.0f;
    lights[3].castsShadows = false;
    lights[2].normalBias = 0.5f;
    return lights;
}

TEST(DirectionalShadowPlanner, ReportsLightsWithoutTilesAndNeverThrows)
{
    const std::vector<DirectionalShadowLightInput> lights = sixLights();
    const std::vector<Bounds> casters{{{-1, 0, -5}, {1, 2, -3}}};
    const DirectionalShadowPlan plan =
        planDirectionalShadows(ShadowSettings{}, testing::kZeroToOneReversed, streetCamera(), lights, casters);
    ASSERT_EQ(plan.lights.size(), 4u);
    EXPECT_EQ(plan.lights[0].lightIndex, 0u);
    EXPECT_EQ(plan.lights[1].lightIndex, 2u);
    EXPECT_EQ(plan.lights[2].lightIndex, 4u);
    EXPECT_EQ(plan.lights[3].lightIndex, 5u);
    EXPECT_EQ(plan.shadowSlots, (std::vector<int>{0, -1, 1, -1, 2, 3}));
    ASSERT_EQ(plan.report.size(), 2u);
    EXPECT_EQ(plan.report[0].lightIndex, 1u);
    EXPECT_EQ(plan.report[0].reason, "shadow strength is 0");
    EXPECT_EQ(plan.report[1].lightIndex, 3u);
    EXPECT_EQ(plan.report[1].reason, "casts no shadows");

    std::vector<DirectionalShadowLightInput> five(5);
    const DirectionalShadowPlan full =
        planDirectionalShadows(ShadowSettings{}, testing::kZeroToOneReversed, streetCamera(), five, casters);
    EXPECT_EQ(full.lights.size(), 4u);
    ASSERT_EQ(full.report.size(), 1u);
    EXPECT_EQ(full.report[0].lightIndex, 4u);
    EXPECT_EQ(full.report[0].reason, "beyond the limit of 4 shadowed directional lights");
    EXPECT_EQ(full.atlas.split(), 4u);
    EXPECT_EQ(full.atlas.tileSize(), 256u);
}

TEST(DirectionalShadowPlanner, TilesViewportsAndUniformsAgree)
{
    ShadowSettings settings;
    settings.directional.filter = ShadowFilter::PCF5x5;
    settings.directional.cascadeBlend = CascadeBlend::Soft;
    const std::vector<DirectionalShadowLightInput> lights = sixLights();
    const std::vector<Bounds> casters{{{-1, 0, -5}, {1, 2, -3}}};
    const DirectionalShadowPlan plan =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, streetCamera(), lights, casters);
    const DirectionalShadowUniforms& u = plan.uniforms;
    EXPECT_EQ(u.cascadeCount, 4);
    EXPECT_EQ(u.defaultFilter, ShadowFilter::PCF5x5);
    EXPECT_EQ(u.cascadeBlend, CascadeBlend::Soft);
    EXPECT_EQ(u.shadowedLightCount, 4);
    EXPECT_EQ(u.atlasSize, 1024.0f);
    // The light's filter is the atlas's PCF5x5 for a light without its own.
    EXPECT_EQ(u.lights[1].strength, 1.0f);
    EXPECT_EQ(u.lights[1].normalBias, 0.5f);
    EXPECT_EQ(u.lights[1].firstTile, 4);
    EXPECT_EQ(u.lights[1].shadowFilter, ShadowFilter::PCF5x5);
    ASSERT_EQ(plan.cascadeData.size(), 4u);
    for (std::uint32_t c = 0; c < 4; ++c) {
        EXPECT_EQ(u.cascades[c].selectionCentre, plan.cascadeData[c].selectionCentre);
        EXPECT_EQ(u.cascades[c].fadeScale, plan.cascadeData[c].fadeScale);
        EXPECT_EQ(u.cascades[c].farDepth, plan.cascadeData[c].farDepth);
        EXPECT_LT(u.cascades[c].selectionRadiusSquared, plan.cullingSpheres[c].radius * plan.cullingSpheres[c].radius);
    }
    for (std::uint32_t slot = 0; slot < 4; ++slot) {
        const ShadowedDirectionalLight& light = plan.lights[slot];
        EXPECT_EQ(light.firstTile, slot * 4);
        ASSERT_EQ(light.cascades.size(), 4u);
        for (std::uint32_t c = 0; c < 4; ++c) {
            const DirectionalCascadePlan& cascade = light.cascades[c];
            EXPECT_EQ(cascade.tile, slot * 4 + c);
            EXPECT_EQ(u.worldToAtlas[cascade.tile], cascade.worldToAtlas);
            EXPECT_EQ(cascade.viewport.x, static_cast<float>(plan.atlas.tileOffset(cascade.tile).x));
            EXPECT_EQ(cascade.viewport.y, static_cast<float>(plan.atlas.tileOffset(cascade.tile).y));
        }
    }
}

// End to end: a receiver picks its cascade as the lit shader does (first sphere with d^2 < r'^2);
// every texel its filter reads with non-zero weight then lies inside that cascade's tile.
TEST(DirectionalShadowPlanner, SelectedCascadeFiltersStayInsideTheirTile)
{
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_real_distribution<float> depth(0.2f, 95.0f);
    for (ShadowFilter filter :
         {ShadowFilter::PCF2x2, ShadowFilter::PCF3x3, ShadowFilter::PCF5x5, ShadowFilter::PCF7x7}) {
        ShadowSettings settings;
        settings.directional.filter = filter;
        const ShadowCamera camera = testing::randomCamera(rng);
        const std::vector<DirectionalShadowLightInput> lights{{testing::randomUnit(rng)}, {testing::randomUnit(rng)}};
        // A caster where the camera stands: in every light's first cascade, so both lights take tiles.
        const std::vector<Bounds> casters{{camera.position - 1.0f, camera.position + 1.0f}};
        const DirectionalShadowPlan plan =
            planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters);
        const glm::vec3 right = glm::cross(camera.forward, camera.up);
        const float tanY = std::tan(0.5f * camera.fovY);
        const float size = static_cast<float>(plan.atlas.atlasSize());
        int selected = 0;
        for (int trial = 0; trial < 500; ++trial) {
            const float d = depth(rng);
            const glm::vec3 p = camera.position + camera.forward * d + camera.up * (unit(rng) * d * tanY) +
                                right * (unit(rng) * d * tanY * camera.aspect);
            std::uint32_t c = 0;
            auto outside = [&](const CascadeData& cascade) {
                return glm::dot(p - cascade.selectionCentre, p - cascade.selectionCentre) >=
                       cascade.selectionRadiusSquared;
            };
            while (c < 4 && outside(plan.uniforms.cascades[c]))
                ++c;
            if (c == 4)
                continue;
            ++selected;
            for (std::uint32_t slot = 0; slot < plan.lights.size(); ++slot) {
                const std::uint32_t tile = plan.lights[slot].firstTile + c;
                const glm::vec2 texel = glm::vec2(plan.uniforms.worldToAtlas[tile] * glm::vec4(p, 1.0f)) * size;
                const glm::vec2 low(plan.atlas.tileOffset(tile));
                const float high = static_cast<float>(plan.atlas.tileSize());
                for (int axis = 0; axis < 2; ++axis) {
                    const TexelWeights w = tentTexelWeights(filter, texel[axis]);
                    for (int k = 0; k < w.count; ++k) {
                        if (w.weights[static_cast<std::size_t>(k)] <= 1e-6f)
                            continue;
                        EXPECT_GE(static_cast<float>(w.first + k), low[axis]) << "filter " << filterSize(filter);
                        EXPECT_LT(static_cast<float>(w.first + k), low[axis] + high) << "filter " << filterSize(filter);
                    }
                }
            }
        }
        EXPECT_GT(selected, 100);
    }
}

TEST(DirectionalShadowPlanner, NoShadowDistanceBeyondTheNearPlane)
{
    ShadowSettings settings;
    settings.maxDistance = 0.05f;
    const std::vector<DirectionalShadowLightInput> lights(2);
    const DirectionalShadowPlan plan =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, streetCamera(), lights, {});
    EXPECT_TRUE(plan.lights.empty());
    ASSERT_EQ(plan.report.size(), 3u);
    EXPECT_FALSE(plan.report[0].lightIndex.has_value());
    EXPECT_EQ(plan.uniforms.shadowedLightCount, 0);
}

TEST(DirectionalShadowPlanner, InvalidSettingsThrow)
{
    ShadowSettings settings;
    settings.directional.cascadeCount = 0;
    EXPECT_THROW(planDirectionalShadows(settings, testing::kZeroToOneReversed, streetCamera(), {}, {}), rhi::Error);
}

TEST(DirectionalShadowPlanner, OneLightOneCascadeUsesTheWholeAtlas)
{
    ShadowSettings settings;
    settings.directional.cascadeCount = 1;
    const std::vector<DirectionalShadowLightInput> lights(1);
    const std::vector<Bounds> casters{{{-1, 0, -5}, {1, 2, -3}}};
    const DirectionalShadowPlan plan =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, streetCamera(), lights, casters);
    EXPECT_EQ(plan.atlas.split(), 1u);
    ASSERT_EQ(plan.lights.size(), 1u);
    const rhi::Viewport v = plan.lights[0].cascades[0].viewport;
    EXPECT_EQ(v.width, 1024.0f);
    EXPECT_EQ(v.x, 0.0f);
}

// Only casters that can shadow what the cascades cover earn a light its tiles: one high above the view toward the
// light does, one far beside the view or wholly below it (past the cascades' far end along the light) does not.
TEST(DirectionalShadowPlanner, ALightWithNoCasterInReachTakesNoTile)
{
    std::vector<DirectionalShadowLightInput> lights(1);
    lights[0].direction = {0.0f, -1.0f, 0.0f};
    const auto plan = [&](const Bounds& caster) {
        return planDirectionalShadows(ShadowSettings{}, testing::kZeroToOneReversed, streetCamera(), lights,
                                      std::vector<Bounds>{caster});
    };
    EXPECT_EQ(plan({{-1, 50, -10}, {1, 52, -8}}).lights.size(), 1u) << "above the view, toward the light";
    EXPECT_EQ(plan({{-1, 0, -5}, {1, 2, -3}}).lights.size(), 1u) << "in the view";
    const DirectionalShadowPlan beside = plan({{900, 0, 0}, {902, 2, 2}});
    EXPECT_TRUE(beside.lights.empty());
    EXPECT_EQ(beside.shadowSlots, std::vector<int>{-1});
    ASSERT_EQ(beside.report.size(), 1u);
    EXPECT_EQ(beside.report[0].reason, "no caster in its cascades' reach");
    EXPECT_EQ(beside.uniforms.shadowedLightCount, 0);
    EXPECT_TRUE(plan({{-1, -900, -10}, {1, -898, -8}}).lights.empty()) << "below every cascade";
}

} // namespace
} // namespace penumbra::shadows
