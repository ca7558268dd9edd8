// Close fit: cascades are bands of view depth, each tile fitted to its frustum slice's light-space bounds.
#include "ShadowTestSupport.hpp"
#include "penumbra/shadows/CascadeSelection.hpp"
#include "penumbra/shadows/CasterCulling.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/TentFilter.hpp"

#include <cstdio>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

// The built-in test scene's camera (scenes::makeShadowTestScene): from (0, 8, -20) at (0, 0, 5), 60 degrees, 16:9.
ShadowCamera sceneCamera()
{
    ShadowCamera camera = testing::uprightCamera(glm::vec3(0.0f, 8.0f, -20.0f), glm::vec3(0.0f, -8.0f, 25.0f));
    camera.fovY = 1.0471976f;
    camera.aspect = 16.0f / 9.0f;
    camera.nearPlane = 0.1f;
    camera.farPlane = 200.0f;
    return camera;
}

DirectionalShadowPlan plan(CascadeProjection projection, const ShadowCamera& camera, glm::vec3 light,
                           CascadeBlend blend = CascadeBlend::Hard, std::span<const Bounds> casters = {})
{
    ShadowSettings settings;
    settings.directional.projection = projection;
    settings.directional.cascadeBlend = blend;
    const std::vector<DirectionalShadowLightInput> lights{{glm::normalize(light)}};
    // Without casters of the test's own, one where the camera stands: the light then has a caster in reach.
    const std::vector<Bounds> atCamera{{camera.position - 1.0f, camera.position + 1.0f}};
    return planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights,
                                  casters.empty() ? std::span<const Bounds>(atCamera) : casters);
}

TEST(CloseFit, TilesAreTighterThanTheStableFitsForTheSameView)
{
    std::mt19937 rng(21);
    int views = 0;
    for (int trial = 0; trial < 50; ++trial) {
        const ShadowCamera camera = trial == 0 ? sceneCamera() : testing::randomCamera(rng);
        const glm::vec3 light = trial == 0 ? glm::vec3(-0.4f, -1.0f, 0.5f) : testing::randomUnit(rng);
        const DirectionalShadowPlan stable = plan(CascadeProjection::Stable, camera, light);
        const DirectionalShadowPlan close = plan(CascadeProjection::Close, camera, light);
        ASSERT_EQ(close.lights.size(), 1u);
        for (std::uint32_t c = 0; c < 4; ++c) {
            const float stableTexels = 1.0f / stable.lights[0].cascades[c].fit.texelSize;
            const float closeTexels = 1.0f / close.lights[0].cascades[c].fit.texelSize;
            if (trial == 0)
                std::printf("[ close    ] test scene view, cascade %u (view depth %.1f..%.1f): %.1f texels per metre "
                            "stable, %.1f close (x%.2f)\n",
                            c, stable.splits.nearOf(c), stable.splits.farOf(c), stableTexels, closeTexels,
                            closeTexels / stableTexels);
            // The slice's bounds lie inside its bounding sphere, so the close tile is never much wider; its filter
            // margin (a few texels) is the most it can lose.
            EXPECT_GT(closeTexels, stableTexels * 0.99f) << "trial " << trial << " cascade " << c;
            if (trial == 0) {
                EXPECT_GT(closeTexels, stableTexels * 1.2f) << "cascade " << c;
            }
        }
        ++views;
    }
    EXPECT_EQ(views, 50);
}

// Points on the view axis and at the picture's corner, through each band: the close fit takes the cascade of their
// view depth, where the stable fit's overlapping spheres take another (an earlier sphere also holds the points
// near a band's start).
TEST(CloseFit, TheCascadeIsChosenByViewDepth)
{
    const ShadowCamera camera = sceneCamera();
    const DirectionalShadowPlan close = plan(CascadeProjection::Close, camera, {-0.4f, -1.0f, 0.5f});
    const DirectionalShadowPlan stable = plan(CascadeProjection::Stable, camera, {-0.4f, -1.0f, 0.5f});
    EXPECT_EQ(close.uniforms.cascadeProjection, CascadeProjection::Close);
    EXPECT_EQ(stable.uniforms.cascadeProjection, CascadeProjection::Stable);
    const glm::vec3 right = glm::cross(camera.forward, camera.up);
    const float tanY = std::tan(0.5f * camera.fovY);
    int stableDiffers = 0;
    for (std::uint32_t c = 0; c < 4; ++c) {
        EXPECT_EQ(close.uniforms.cascades[c].farDepth, close.splits.farOf(c));
        for (const float along : {0.02f, 0.5f, 0.98f}) {
            const float depth = close.splits.nearOf(c) + along * (close.splits.farOf(c) - close.splits.nearOf(c));
            for (const float corner : {0.0f, 0.99f}) {
                const glm::vec3 p = camera.position + camera.forward * depth +
                                    (camera.up * tanY + right * (tanY * camera.aspect)) * (corner * depth);
                EXPECT_EQ(selectCascade(close.uniforms, p, depth).index, c) << "depth " << depth;
                stableDiffers += selectCascade(stable.uniforms, p, depth).index != c;
            }
        }
    }
    EXPECT_EQ(selectCascade(close.uniforms, camera.position + camera.forward * 101.0f, 101.0f).index, 4u);
    EXPECT_GT(stableDiffers, 0) << "the stable fit's bands are not view depth bands";
}

// Every receiver in the view takes a cascade by its depth; its normal offset and every texel its filter reads lie
// inside that cascade's tile, in every blend (soft and dither overlap the slices by the fade band).
TEST(CloseFit, SelectedCascadeFiltersStayInsideTheirTile)
{
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_real_distribution<float> along(0.0f, 1.0f);
    for (const CascadeBlend blend : {CascadeBlend::Hard, CascadeBlend::Soft, CascadeBlend::Dither})
        for (ShadowFilter filter : {ShadowFilter::PCF2x2, ShadowFilter::PCF5x5, ShadowFilter::PCF7x7}) {
            ShadowSettings settings;
            settings.directional.filter = filter;
            settings.directional.cascadeBlend = blend;
            settings.directional.projection = CascadeProjection::Close;
            const ShadowCamera camera = testing::randomCamera(rng);
            const std::vector<DirectionalShadowLightInput> lights{{testing::randomUnit(rng)},
                                                                  {testing::randomUnit(rng)}};
            const std::vector<Bounds> casters{{camera.position - 1.0f, camera.position + 1.0f}};
            const DirectionalShadowPlan p =
                planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters);
            const glm::vec3 right = glm::cross(camera.forward, camera.up);
            const float tanY = std::tan(0.5f * camera.fovY);
            const float size = static_cast<float>(p.atlas.atlasSize());
            const float shadowFar = p.splits.farOf(3);
            for (int trial = 0; trial < 500; ++trial) {
                const float d = camera.nearPlane + along(rng) * (shadowFar - camera.nearPlane) * 0.999f;
                const glm::vec3 point = camera.position + camera.forward * d + camera.up * (unit(rng) * d * tanY) +
                                        right * (unit(rng) * d * tanY * camera.aspect);
                const CascadeSelection s = selectCascade(p.uniforms, point, d);
                ASSERT_LT(s.index, 4u);
                // With a blend, the next cascade is read too wherever the fade has begun.
                const std::uint32_t last =
                    blend != CascadeBlend::Hard && s.fade < 1.0f && s.index < 3 ? s.index + 1 : s.index;
                for (std::uint32_t c = s.index; c <= last; ++c)
                    for (std::uint32_t slot = 0; slot < p.lights.size(); ++slot) {
                        const std::uint32_t tile = p.lights[slot].firstTile + c;
                        // The receiver's normal offset, its full length in the worst direction (the light plane).
                        const glm::vec3 offset = right * p.uniforms.cascades[c].normalBias;
                        const glm::vec2 texel =
                            glm::vec2(p.uniforms.worldToAtlas[tile] * glm::vec4(point + offset, 1.0f)) * size;
                        const glm::vec2 low(p.atlas.tileOffset(tile));
                        const float high = static_cast<float>(p.atlas.tileSize());
                        for (int axis = 0; axis < 2; ++axis) {
                            const TexelWeights w = tentTexelWeights(filter, texel[axis]);
                            for (int k = 0; k < w.count; ++k) {
                                if (w.weights[static_cast<std::size_t>(k)] <= 1e-6f)
                                    continue;
                                EXPECT_GE(static_cast<float>(w.first + k), low[axis]) << "cascade " << c;
                                EXPECT_LT(static_cast<float>(w.first + k), low[axis] + high) << "cascade " << c;
                            }
                        }
                    }
            }
        }
}

// Translation moves the slice's light-space bounds as a whole: every tile keeps its size and a fixed world point keeps
// its sub-texel position in the atlas, as in the stable fit. Turning changes the bounds' size, and the texels swim.
TEST(CloseFit, TranslatingTheCameraKeepsTheTexelSizeAndMovesTexelsByWholeTexels)
{
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> step(-3.0f, 3.0f);
    const ShadowCamera camera = sceneCamera();
    const glm::vec3 light{-0.4f, -1.0f, 0.5f};
    const glm::vec3 point = camera.position + camera.forward * 6.0f + glm::vec3(0.3f, 0.1f, -0.2f);
    const DirectionalShadowPlan reference = plan(CascadeProjection::Close, camera, light);
    const float texel = reference.lights[0].cascades[0].fit.texelSize;
    const auto atlasTexel = [&](const DirectionalShadowPlan& p) {
        return glm::vec2(p.uniforms.worldToAtlas[0] * glm::vec4(point, 1.0f)) * float(p.atlas.atlasSize());
    };
    for (int trial = 0; trial < 200; ++trial) {
        ShadowCamera translated = camera;
        translated.position += glm::vec3(step(rng), step(rng), step(rng)) * texel;
        const DirectionalShadowPlan moved = plan(CascadeProjection::Close, translated, light);
        for (std::uint32_t c = 0; c < 4; ++c)
            EXPECT_EQ(moved.lights[0].cascades[c].fit.texelSize, reference.lights[0].cascades[c].fit.texelSize)
                << "trial " << trial << " cascade " << c;
        const glm::vec2 delta = atlasTexel(moved) - atlasTexel(reference);
        EXPECT_NEAR(delta.x, std::round(delta.x), 2e-3f) << "trial " << trial;
        EXPECT_NEAR(delta.y, std::round(delta.y), 2e-3f) << "trial " << trial;
    }
    ShadowCamera turned = camera;
    turned.forward = glm::normalize(camera.forward + 0.01f * glm::cross(camera.forward, camera.up));
    EXPECT_NE(plan(CascadeProjection::Close, turned, light).lights[0].cascades[0].fit.texelSize, texel);
}

// The culling bias follows the bands: a caster wholly inside the previous cascade's slice (its depth range scaled
// by the culling factor) is skipped, one reaching past it or outside the frustum is drawn.
TEST(CloseFit, CullingBiasSkipsCastersWhollyInsideThePreviousSlice)
{
    const ShadowCamera camera = sceneCamera();
    const glm::vec3 inFirst = camera.position + camera.forward * 5.0f;
    const glm::vec3 beyond = camera.position + camera.forward * 30.0f;
    const glm::vec3 right = glm::cross(camera.forward, camera.up);
    const std::vector<Bounds> casters{{inFirst - 0.2f, inFirst + 0.2f},
                                      {beyond - 0.2f, beyond + 0.2f},
                                      {inFirst + right * 40.0f - 0.2f, inFirst + right * 40.0f + 0.2f}};
    const DirectionalShadowPlan p =
        plan(CascadeProjection::Close, camera, {0.0f, -1.0f, 0.01f}, CascadeBlend::Hard, casters);
    ASSERT_GE(p.splits.farOf(0), 10.0f) << "the first cascade holds the first caster";
    const FrustumSlice first{camera, p.splits.nearOf(0), p.splits.farOf(0)};
    const float factor = cascadeBlendCullingFactor(ShadowSettings{}.directional.cascadeFade);
    EXPECT_TRUE(insideFrustumSlice(casters[0], first, factor));
    EXPECT_FALSE(insideFrustumSlice(casters[1], first, factor));
    EXPECT_FALSE(insideFrustumSlice(casters[2], first, factor));
    const CasterCullingResult withBias =
        cullCloseFitShadowCasters(p.lights[0].cascades[1].fit,
                                  lightSpaceCasters(p.lights[0].cascades[1].fit.basis, casters), first, factor);
    const CasterCullingResult without =
        cullCloseFitShadowCasters(p.lights[0].cascades[1].fit,
                                  lightSpaceCasters(p.lights[0].cascades[1].fit.basis, casters), std::nullopt, factor);
    EXPECT_EQ(withBias.culledByBias, without.culledByBias + (without.overlapping > 0 ? 1u : 0u));
    for (const std::uint32_t i : withBias.casters)
        EXPECT_NE(i, 0u) << "the caster inside the first slice is skipped";
    EXPECT_EQ(p.lights[0].cascades[1].casters.casters, withBias.casters);
}

} // namespace
} // namespace penumbra::shadows
