#include "GpuTesting.hpp"
#include "TestPattern.hpp"

namespace penumbra::testing {
namespace {

using WindingTest = GpuTest;

const glm::vec4 white(1, 1, 1, 1);
// Counter-clockwise in canonical NDC (y up): right, then up, then back.
const std::vector<pattern::PatternVertex> counterClockwise = {{{-0.8f, -0.8f, 2.0f}, white},
                                                              {{0.8f, -0.8f, 2.0f}, white},
                                                              {{0.0f, 0.8f, 2.0f}, white}};
const std::vector<pattern::PatternVertex> clockwise = {counterClockwise[0], counterClockwise[2], counterClockwise[1]};

bool drawn(pattern::PatternRenderer& renderer, const std::vector<pattern::PatternVertex>& triangle, rhi::CullMode cull)
{
    renderer.render(triangle, cull);
    return pixel(renderer.color(), 16, 20) == Rgba{255, 255, 255, 255};
}

TEST_F(WindingTest, CounterClockwiseIsFrontFacing)
{
    pattern::PatternRenderer renderer(*device, {.width = 32, .height = 32});
    EXPECT_TRUE(drawn(renderer, counterClockwise, rhi::CullMode::Back));
    EXPECT_FALSE(drawn(renderer, counterClockwise, rhi::CullMode::Front));
    EXPECT_FALSE(drawn(renderer, clockwise, rhi::CullMode::Back));
    EXPECT_TRUE(drawn(renderer, clockwise, rhi::CullMode::Front));
    EXPECT_TRUE(drawn(renderer, clockwise, rhi::CullMode::None));
}

} // namespace
} // namespace penumbra::testing
