// The lit pass with FrameDesc::msaa: an unlit white square turned 20 degrees in front of the background, 128 x 128.
// Without MSAA each pixel is the square's white or the background (the negative control); with 4 samples the pixels
// along its four edges take blends of the two, and every other pixel keeps its colour, since shading still runs
// once per pixel.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"

#include <array>
#include <cstring>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kMsaaLitSize = 128;

scene::Scene turnedSquare()
{
    scene::Scene scene;
    scene::MeshData mesh;
    for (const glm::vec2 p : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
        mesh.vertices.push_back({.position = {p, 0.0f}, .normal = {0, 0, 1}, .uv = 0.5f * p + 0.5f});
    mesh.indices = {0, 1, 2, 0, 2, 3};
    scene::updateBounds(mesh);
    const std::uint32_t square = scene.addMesh(std::move(mesh));
    const std::uint32_t white = scene.addMaterial({.name = "white", .baseColor = {1, 1, 1, 1}, .unlit = true});
    scene.addObject("square", square, white, glm::rotate(glm::mat4(1.0f), glm::radians(20.0f), glm::vec3(0, 0, 1)));
    scene.lights = {{.name = "sun", .direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.4f))}};
    scene.camera = scene::lookAt({0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, 0.8f);
    scene.validate();
    return scene;
}

std::uint32_t litMultisampleCount(const rhi::Device& device)
{
    const std::array targets{render::kLitColorFormat, render::kLitDepthFormat};
    return lowestMultisampleCount(device.capabilities(), targets);
}

class MsaaLitTest : public GpuTest {
protected:
    rhi::Image render(const scene::Scene& scene, std::uint32_t msaa)
    {
        return renderLit(*device, scene, litFrame(kMsaaLitSize, kMsaaLitSize, true, msaa));
    }
};

struct Blends {
    std::size_t square = 0; // the square's white
    std::size_t intermediate = 0; // neither white nor the background
};

Blends countBlends(const rhi::Image& image)
{
    const Rgba background = pixel(image, 0, 0);
    const Rgba white{255, 255, 255, 255};
    Blends b;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const Rgba p = pixel(image, x, y);
            b.square += p == white ? 1 : 0;
            b.intermediate += p != white && p != background ? 1 : 0;
        }
    return b;
}

TEST_F(MsaaLitTest, SquareEdgesAreAntiAliased)
{
    const std::uint32_t samples = litMultisampleCount(*device);
    ASSERT_NE(samples, 0u) << "the device offers no multisampled lit pass";
    const scene::Scene scene = turnedSquare();
    const rhi::Image single = render(scene, 1);
    const rhi::Image multi = render(scene, samples);
    const Blends hard = countBlends(single), smooth = countBlends(multi);
    savePicture(multi, fmt::format("{}/msaa-lit-square-{}x", configuration(), samples));
    ASSERT_GT(hard.square, std::size_t(kMsaaLitSize) * kMsaaLitSize / 5) << "the square covers too little";
    EXPECT_EQ(hard.intermediate, 0u) << savePicture(single, configuration() + "/msaa-lit-square-1x");
    // The square's outline is about 4 x 50 pixels long.
    EXPECT_GT(smooth.intermediate, 150u) << savePicture(multi, configuration() + "/msaa-lit-square");
    std::size_t changed = 0;
    for (std::size_t i = 0; i < single.bytes.size(); i += 4)
        changed += std::memcmp(&single.bytes[i], &multi.bytes[i], 4) != 0 ? 1 : 0;
    EXPECT_LE(changed, smooth.intermediate) << "pixels away from the edges changed";
    fmt::print("[ msaa ] lit {}x: {} blended edge pixels, {} changed (1x: {} blended)\n", samples, smooth.intermediate,
               changed, hard.intermediate);
}

// A count the RHI does not know, and the counts the device does not offer, named with the ones it does.
TEST_F(MsaaLitTest, CountsTheDeviceLacksAreRefusedByName)
{
    const scene::Scene scene = turnedSquare();
    try {
        render(scene, 3);
        ADD_FAILURE() << "msaa 3 was accepted";
    } catch (const rhi::UnsupportedError& e) {
        ADD_FAILURE() << "msaa 3 raised UnsupportedError: " << e.what();
    } catch (const rhi::Error& e) {
        EXPECT_STREQ(e.what(), "FrameDesc::msaa: 3 is not 1, 2, 4 or 8");
    }
    const std::array targets{render::kLitColorFormat, render::kLitDepthFormat};
    const std::uint32_t offered = device->capabilities().sampleCounts(targets);
    for (std::uint32_t count = 2; count <= 8; count *= 2) {
        if (offered & count)
            continue;
        try {
            render(scene, count);
            ADD_FAILURE() << "msaa " << count << " was accepted";
        } catch (const rhi::UnsupportedError& e) {
            EXPECT_EQ(std::string(e.what()),
                      fmt::format("msaa {}: {} offers {} samples per pixel for the lit pass (RGBA8 colour, D32F depth)",
                                  count, device->capabilities().device, rhi::sampleCountList(offered)));
        }
    }
}

} // namespace
} // namespace penumbra::testing
