#include "GpuTesting.hpp"

#include <cmath>
#include <cstring>
#include <glm/mat4x4.hpp>

namespace penumbra::testing {
namespace {

using FormatsTest = GpuTest;

float halfToFloat(std::uint16_t h)
{
    const int exponent = (h >> 10) & 0x1F, mantissa = h & 0x3FF;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 0)
        return sign * std::ldexp(float(mantissa), -24);
    return sign * std::ldexp(float(mantissa | 0x400), exponent - 25);
}

glm::vec4 texelColor(const rhi::Image& image, std::uint32_t x, std::uint32_t y)
{
    const std::byte* p = image.texel(x, y);
    glm::vec4 c;
    for (int i = 0; i < 4; ++i) {
        if (image.format == rhi::Format::RGBA8) {
            c[i] = float(std::uint8_t(p[i])) / 255.0f;
        } else if (image.format == rhi::Format::RGBA16F) {
            std::uint16_t h;
            std::memcpy(&h, p + 2 * i, 2);
            c[i] = halfToFloat(h);
        } else {
            std::memcpy(&c[i], p + 4 * i, 4);
        }
    }
    return c;
}

std::unique_ptr<rhi::Framebuffer> colorFramebuffer(rhi::Device& device, const rhi::Texture& texture,
                                                   std::uint32_t layer)
{
    const rhi::Attachment attachment{&texture, layer};
    return device.createFramebuffer({.colors = {&attachment, 1}});
}

void clearLayer(rhi::Device& device, const rhi::Texture& texture, std::uint32_t layer, glm::vec4 color)
{
    auto framebuffer = colorFramebuffer(device, texture, layer);
    auto commands = device.createCommandList();
    commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = color});
    commands->endPass();
    device.submit(*commands);
}

TEST_F(FormatsTest, ColorFormatsKeepTheClearValue)
{
    const glm::vec4 value(0.2f, 0.4f, 0.6f, 1.0f); // exact in RGBA8: 51, 102, 153, 255
    for (rhi::Format format : {rhi::Format::RGBA8, rhi::Format::RGBA16F, rhi::Format::RGBA32F}) {
        auto texture = device->createTexture(
            {.width = 4, .height = 4, .format = format, .usage = rhi::TextureUsage::RenderTarget});
        clearLayer(*device, *texture, 0, value);
        const glm::vec4 read = texelColor(rhi::readTexture(*device, *texture), 3, 2);
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(read[i], value[i], format == rhi::Format::RGBA16F ? 1e-3f : 1e-6f)
                << rhi::formatName(format) << " channel " << i;
    }
}

TEST_F(FormatsTest, DepthFormatsStoreTheDrawnDepth)
{
    auto vertex = device->createShader({rhi::ShaderStage::Vertex, R"(#version 450
layout(std140, binding = 0) uniform Projection { mat4 projection; } block;
void main() {
    const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
    gl_Position = block.projection * vec4(corners[gl_VertexIndex], -3.0, 1.0);
}
)",
                                        "depth.vert"});
    auto fragment = device->createShader({rhi::ShaderStage::Fragment, "#version 450\nvoid main() {}\n", "depth.frag"});
    const glm::mat4 projection = device->conventions().orthographic(-1, 1, -1, 1, 1.0f, 5.0f);
    auto uniforms = device->createBuffer({.size = sizeof(glm::mat4), .usage = rhi::BufferUsage::Uniform});
    uniforms->writeObject(projection);
    for (auto [format, tolerance] : {std::pair{rhi::Format::D16, 2e-5f}, std::pair{rhi::Format::D24S8, 1e-6f},
                                     std::pair{rhi::Format::D32F, 1e-6f}}) {
        auto pipeline = device->createPipeline({.vertex = vertex.get(),
                                                .fragment = fragment.get(),
                                                .depth = {.test = true, .write = true},
                                                .depthFormat = format});
        auto texture = device->createTexture(
            {.width = 8, .height = 8, .format = format, .usage = rhi::TextureUsage::RenderTarget});
        auto framebuffer = device->createFramebuffer({.depth = {texture.get(), 0}});
        auto commands = device->createCommandList();
        commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = std::nullopt});
        commands->bindPipeline(*pipeline);
        commands->bindUniformBuffer(0, *uniforms, 0, sizeof(glm::mat4));
        commands->draw(3);
        commands->endPass();
        device->submit(*commands);
        const float depth = rhi::readDepth(*device, *texture).at(5, 6);
        EXPECT_NEAR(device->conventions().viewDepth(projection, depth), 3.0f, tolerance * 4.0f)
            << rhi::formatName(format) << " stored " << depth;
    }
}

TEST_F(FormatsTest, ArrayLayersAreSeparateTargets)
{
    auto array = device->createTexture({.width = 4,
                                        .height = 4,
                                        .layers = 3,
                                        .array = true,
                                        .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled});
    const glm::vec4 colors[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
    for (std::uint32_t layer = 0; layer < 3; ++layer)
        clearLayer(*device, *array, layer, colors[layer]);
    for (std::uint32_t layer = 0; layer < 3; ++layer)
        EXPECT_EQ(texelColor(rhi::readTexture(*device, *array, layer), 1, 1), colors[layer]) << "layer " << layer;
}

TEST_F(FormatsTest, UploadsAndCopiesKeepRowZeroOnTop)
{
    constexpr std::uint32_t w = 4, h = 3;
    std::vector<std::byte> rows(w * h * 4);
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = std::byte(i * 7 + 1); // row 0 differs from every other row
    auto source = device->createTexture({.width = w, .height = h, .layers = 2, .array = true});
    device->writeTexture(*source, 1, 0, rows);
    EXPECT_EQ(rhi::readTexture(*device, *source, 1).bytes, rows);

    auto destination = device->createTexture({.width = w, .height = h});
    auto buffer = device->createBuffer({.size = rows.size(), .usage = rhi::BufferUsage::Readback});
    auto copied = device->createBuffer({.size = rows.size(), .usage = rhi::BufferUsage::Readback});
    auto commands = device->createCommandList();
    commands->copyTexture(*source, 1, *destination, 0);
    commands->copyTextureToBuffer(*destination, 0, 0, *buffer);
    commands->copyBuffer(*buffer, 0, *copied, 0, rows.size());
    device->submit(*commands);
    std::vector<std::byte> read(rows.size());
    copied->read(0, read);
    EXPECT_EQ(read, rows);
}

} // namespace
} // namespace penumbra::testing
