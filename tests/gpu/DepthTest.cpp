#include "GpuTesting.hpp"
#include "TestPattern.hpp"

namespace penumbra::testing {
namespace {

using DepthTest = GpuTest;

std::vector<pattern::PatternVertex> fullTriangle(float viewDepth, glm::vec4 color)
{
    return {{{-1.0f, -1.0f, viewDepth}, color}, {{3.0f, -1.0f, viewDepth}, color}, {{-1.0f, 3.0f, viewDepth}, color}};
}

TEST_F(DepthTest, NearerTriangleWinsWhateverTheOrder)
{
    pattern::PatternRenderer renderer(*device, {.width = 16, .height = 16});
    const auto nearRed = fullTriangle(3.0f, {1, 0, 0, 1});
    const auto farGreen = fullTriangle(6.0f, {0, 1, 0, 1});
    for (bool nearFirst : {true, false}) {
        std::vector<pattern::PatternVertex> both = nearFirst ? nearRed : farGreen;
        const auto& second = nearFirst ? farGreen : nearRed;
        both.insert(both.end(), second.begin(), second.end());
        renderer.render(both);
        EXPECT_EQ(pixel(renderer.color(), 8, 8), (Rgba{255, 0, 0, 255})) << "near drawn first: " << nearFirst;
    }
}

TEST_F(DepthTest, DepthReadbackGivesLinearViewDepth)
{
    pattern::PatternRenderer renderer(*device, {.width = 16, .height = 16});
    for (float viewDepth : {0.5f, 3.0f, 42.0f}) {
        renderer.render(fullTriangle(viewDepth, {1, 1, 1, 1}));
        const float d = renderer.depth().at(8, 8);
        EXPECT_NEAR(device->conventions().viewDepth(renderer.projection(), d), viewDepth, viewDepth * 1e-4f)
            << "window depth " << d;
    }
}

TEST_F(DepthTest, ClearedDepthIsTheFarPlane)
{
    pattern::PatternRenderer renderer(*device, {.width = 16, .height = 16});
    renderer.render({});
    EXPECT_EQ(renderer.depth().at(3, 3), device->conventions().farDepth());
}

} // namespace
} // namespace penumbra::testing
