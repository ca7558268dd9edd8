#include "penumbra/shadows/CascadeSplits.hpp"

#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

void expectSplits(const CascadeSplits& s, std::initializer_list<float> expected)
{
    ASSERT_EQ(s.count + 1, expected.size());
    std::size_t i = 0;
    for (float d : expected)
        EXPECT_FLOAT_EQ(s.distances[i++], d) << "split " << i - 1;
}

TEST(CascadeSplits, RatiosOfTheMaxDistance)
{
    expectSplits(cascadeSplits(0.1f, 1000.0f, 100.0f, 4, {0.1f, 0.25f, 0.5f}), {0.1f, 10.0f, 25.0f, 50.0f, 100.0f});
}

TEST(CascadeSplits, ShadowDistanceIsLimitedByTheFarPlane)
{
    expectSplits(cascadeSplits(0.1f, 40.0f, 100.0f, 4, {0.1f, 0.25f, 0.5f}), {0.1f, 4.0f, 10.0f, 20.0f, 40.0f});
}

TEST(CascadeSplits, FewerCascadesUseTheFirstRatios)
{
    expectSplits(cascadeSplits(0.5f, 1000.0f, 60.0f, 1, {0.1f, 0.25f, 0.5f}), {0.5f, 60.0f});
    expectSplits(cascadeSplits(0.5f, 1000.0f, 60.0f, 2, {0.1f, 0.25f, 0.5f}), {0.5f, 6.0f, 60.0f});
    expectSplits(cascadeSplits(0.5f, 1000.0f, 60.0f, 3, {0.1f, 0.25f, 0.5f}), {0.5f, 6.0f, 15.0f, 60.0f});
}

TEST(CascadeSplits, SplitsBeforeTheNearPlaneAreClampedToIt)
{
    expectSplits(cascadeSplits(2.0f, 1000.0f, 10.0f, 4, {0.0f, 0.1f, 0.5f}), {2.0f, 2.0f, 2.0f, 5.0f, 10.0f});
}

} // namespace
} // namespace penumbra::shadows
