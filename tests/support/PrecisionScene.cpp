#include "PrecisionScene.hpp"

#include "GpuTesting.hpp"
#include "TestPattern.hpp"

namespace penumbra::testing {

ZFighting countZFighting(rhi::Device& device)
{
    pattern::PatternRenderer renderer(device, {.width = 64, .height = 64, .zNear = 0.1f, .zFar = 100000.0f});
    // Eight horizontal strips at different distances, each slanted in depth from left to right,
    // so the result does not hang on how one pair of vertex depths happens to round.
    auto slantedStrip = [](int strip, float depth, glm::vec4 color) {
        const float top = 1.0f - 0.25f * float(strip), bottom = top - 0.25f;
        const pattern::PatternVertex a{{-1, bottom, depth}, color}, b{{1, bottom, depth + 100}, color},
            c{{1, top, depth + 100}, color}, d{{-1, top, depth}, color};
        return std::vector<pattern::PatternVertex>{a, b, c, a, c, d};
    };
    std::vector<pattern::PatternVertex> farther, nearer;
    for (int strip = 0; strip < 8; ++strip) {
        const float depth = 10000.0f + 123.4f * float(strip);
        const auto far = slantedStrip(strip, depth + 1.0f, {0, 1, 0, 1});
        const auto near = slantedStrip(strip, depth, {1, 0, 0, 1});
        farther.insert(farther.end(), far.begin(), far.end());
        nearer.insert(nearer.end(), near.begin(), near.end());
    }
    farther.insert(farther.end(), nearer.begin(), nearer.end());
    renderer.render(farther);

    const rhi::Image image = renderer.color();
    ZFighting result{0, int(image.width * image.height)};
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            result.fighting += pixel(image, x, y) != Rgba{255, 0, 0, 255};
    return result;
}

} // namespace penumbra::testing
