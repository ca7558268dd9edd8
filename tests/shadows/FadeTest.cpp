#include "penumbra/shadows/CascadeData.hpp"
#include "penumbra/shadows/ShadowFade.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

TEST(ShadowFade, DistanceFadeReciprocals)
{
    const ShadowDistanceFade fade = shadowDistanceFade(ShadowSettings{});
    EXPECT_FLOAT_EQ(fade.inverseMaxDistance, 1.0f / 100.0f);
    EXPECT_FLOAT_EQ(fade.inverseDistanceFade, 1.0f / 0.1f);
    EXPECT_FLOAT_EQ(fade.inverseSphereCascadeFade, 1.0f / (1.0f - 0.9f * 0.9f));
    EXPECT_FLOAT_EQ(fade.inverseDepthCascadeFade, 1.0f / 0.1f);
}

TEST(ShadowFade, DistanceFadeRunsOverTheLastFractionOfTheMaxDistance)
{
    ShadowSettings settings;
    settings.maxDistance = 50.0f;
    settings.distanceFade = 0.2f;
    const ShadowDistanceFade fade = shadowDistanceFade(settings);
    auto strength = [&](float depth) {
        return fadedShadowStrength(depth, fade.inverseMaxDistance, fade.inverseDistanceFade);
    };
    EXPECT_FLOAT_EQ(strength(0.0f), 1.0f);
    EXPECT_FLOAT_EQ(strength(40.0f), 1.0f); // fade starts at (1 - 0.2) * 50
    EXPECT_NEAR(strength(45.0f), 0.5f, 1e-5f);
    EXPECT_NEAR(strength(50.0f), 0.0f, 1e-6f);
    EXPECT_EQ(strength(60.0f), 0.0f);
}

TEST(ShadowFade, CascadeFadeOnSquaredDistanceKeepsTheConfiguredBand)
{
    ShadowSettings settings;
    settings.directional.cascadeFade = 0.25f;
    const ShadowDistanceFade fade = shadowDistanceFade(settings);
    const CascadeData cascade = cascadeData({{0.0f, 0.0f, 0.0f}, 20.0f}, 0.05f, ShadowFilter::PCF3x3, 30.0f);
    const float r = std::sqrt(cascade.selectionRadiusSquared);
    auto strength = [&](float distance) {
        return fadedShadowStrength(distance * distance, cascade.fadeScale, fade.inverseSphereCascadeFade);
    };
    EXPECT_FLOAT_EQ(strength(0.0f), 1.0f);
    EXPECT_NEAR(strength(0.75f * r), 1.0f, 1e-5f); // the band is the outer 25% of the radius
    EXPECT_GT(strength(0.8f * r), 0.0f);
    EXPECT_LT(strength(0.8f * r), 1.0f);
    EXPECT_NEAR(strength(r), 0.0f, 1e-5f);
}

TEST(CascadeData, SphereShrunkByTheFilterAndNormalBiasOverTheTexelDiagonal)
{
    const Sphere sphere{{1.0f, 2.0f, 3.0f}, 10.0f};
    const float factors[] = {1.0f, 2.0f, 3.0f, 4.0f};
    for (ShadowFilter filter :
         {ShadowFilter::PCF2x2, ShadowFilter::PCF3x3, ShadowFilter::PCF5x5, ShadowFilter::PCF7x7}) {
        const float factor = factors[static_cast<int>(filter)];
        EXPECT_EQ(normalBiasFilterFactor(filter), factor);
        const CascadeData c = cascadeData(sphere, 0.1f, filter, 30.0f);
        const float shrunk = 10.0f - 0.1f * factor;
        EXPECT_EQ(c.selectionCentre, sphere.centre);
        EXPECT_FLOAT_EQ(c.selectionRadiusSquared, shrunk * shrunk);
        EXPECT_FLOAT_EQ(c.fadeScale, 1.0f / (shrunk * shrunk));
        EXPECT_FLOAT_EQ(c.normalBias, 0.1f * factor * std::sqrt(2.0f));
    }
    EXPECT_EQ(filterSize(ShadowFilter::PCF2x2), 2);
    EXPECT_EQ(filterSize(ShadowFilter::PCF3x3), 3);
    EXPECT_EQ(filterSize(ShadowFilter::PCF5x5), 5);
    EXPECT_EQ(filterSize(ShadowFilter::PCF7x7), 7);
}

} // namespace
} // namespace penumbra::shadows
