// The spot and point lights a frame's contact march goes towards (shadows::nearestContactLights).
#include "penumbra/shadows/ContactLights.hpp"

#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

TEST(ContactLightsTest, NearestReachFirst)
{
    // Light 7 is the nearest to the camera but reaches no farther than 1 m; light 3 is farther and reaches the
    // camera; light 5 is far and reaches little.
    const ContactLightCandidate lights[] = {
        {.light = 5, .position = {0.0f, 0.0f, 40.0f}, .range = 5.0f},
        {.light = 7, .position = {0.0f, 0.0f, 4.0f}, .range = 1.0f},
        {.light = 3, .position = {0.0f, 0.0f, 10.0f}, .range = 20.0f},
    };
    EXPECT_EQ(nearestContactLights({0.0f, 0.0f, 0.0f}, lights, 2), (std::vector<std::uint32_t>{3, 7}));
    EXPECT_EQ(nearestContactLights({0.0f, 0.0f, 0.0f}, lights, 4), (std::vector<std::uint32_t>{3, 7, 5}));
    EXPECT_TRUE(nearestContactLights({0.0f, 0.0f, 0.0f}, lights, 0).empty());
}

// Inside several lights' reach, the nearest light first; at equal distances, the lower index.
TEST(ContactLightsTest, TiesGoToTheNearerThenLowerIndex)
{
    const ContactLightCandidate lights[] = {
        {.light = 2, .position = {3.0f, 0.0f, 0.0f}, .range = 10.0f},
        {.light = 1, .position = {-3.0f, 0.0f, 0.0f}, .range = 10.0f},
        {.light = 0, .position = {0.0f, 2.0f, 0.0f}, .range = 10.0f},
    };
    EXPECT_EQ(nearestContactLights({0.0f, 0.0f, 0.0f}, lights, 3), (std::vector<std::uint32_t>{0, 1, 2}));
}

} // namespace
} // namespace penumbra::shadows
