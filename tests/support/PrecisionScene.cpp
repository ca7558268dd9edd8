#include "PrecisionScene.hpp"

#include "GpuTesting.hpp"
#include "TestPattern.hpp"

namespace penumbra::testing {

ZFighting countZFighting(rhi::Device& device)
{
    pattern::PatternRenderer renderer(device, {.width = 64, .height = 64, .zNear = 0.1f, .zFar = 100000.0f});
    auto slantedQuad = [](float depth, glm::vec4 color) {
        // Depth grows from left to right so the pixels sample many depth values.
        const pattern::PatternVertex a{{-1, -1, depth}, color}, b{{1, -1, depth + 100}, color},
            c{{1, 1, depth + 100}, color}, d{{-1, 1, depth}, color};
        return std::vector<pattern::PatternVertex>{a, b, c, a, c, d};
    };
    std::vector<pattern::PatternVertex> quads = slantedQuad(10001.0f, {0, 1, 0, 1});
    const auto nearer = slantedQuad(10000.0f, {1, 0, 0, 1});
    quads.insert(quads.end(), nearer.begin(), nearer.end());
    renderer.render(quads);

    const rhi::Image image = renderer.color();
    ZFighting result{0, int(image.width * image.height)};
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            result.fighting += pixel(image, x, y) != Rgba{255, 0, 0, 255};
    return result;
}

} // namespace penumbra::testing
