#include "GpuTesting.hpp"

#include "penumbra/shaders/ShaderLibrary.hpp"

#include <glm/vec2.hpp>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kSize = 64;

// Draws with a vertex shader that places per-vertex NDC corners moved by a per-instance offset,
// and a fragment shader that outputs a colour from a uniform block (one aligned block per draw).
class DrawStateTest : public GpuTest {
protected:
    void SetUp() override
    {
        GpuTest::SetUp();
        vertex = device->createShader({rhi::ShaderStage::Vertex, R"(#version 450
layout(location = 0) in vec2 corner;
layout(location = 1) in vec2 instanceOffset;
void main() { gl_Position = vec4(corner + instanceOffset, 0.5, 1.0); }
)",
                                       "instanced.vert"});
        fragment = device->createShader({rhi::ShaderStage::Fragment, R"(#version 450
layout(std140, binding = 0) uniform Paint { vec4 color; } paint;
layout(location = 0) out vec4 outColor;
void main() { outColor = paint.color; }
)",
                                         "paint.frag"});
        stride = device->capabilities().uniformBufferOffsetAlignment;
        paints = device->createBuffer({.size = stride * 8, .usage = rhi::BufferUsage::Uniform});
        target = device->createTexture({.width = kSize, .height = kSize, .usage = rhi::TextureUsage::RenderTarget});
        const rhi::Attachment attachment{target.get(), 0};
        framebuffer = device->createFramebuffer({.colors = {&attachment, 1}});
        commands = device->createCommandList();
        // One CCW triangle covering the viewport (room for the four corners of a quad), and per-instance offsets.
        const glm::vec2 corners[3] = {{-1, -1}, {3, -1}, {-1, 3}};
        quad = device->createBuffer({.size = 4 * sizeof(glm::vec2), .usage = rhi::BufferUsage::Vertex});
        quad->write(0, std::as_bytes(std::span(corners)));
        setOffsets({{0, 0}});
    }

    std::unique_ptr<rhi::Pipeline> pipeline(rhi::ColorTarget colorTarget = {})
    {
        return device->createPipeline({
            .vertex = vertex.get(),
            .fragment = fragment.get(),
            .vertexLayout = {.buffers = {{.stride = sizeof(glm::vec2)},
                                         {.stride = sizeof(glm::vec2), .perInstance = true}},
                             .attributes = {{.location = 0, .format = rhi::VertexFormat::Float2, .buffer = 0},
                                            {.location = 1, .format = rhi::VertexFormat::Float2, .buffer = 1}}},
            .cull = rhi::CullMode::Back,
            .colorTargets = {colorTarget},
        });
    }

    void setPaint(std::uint32_t slot, glm::vec4 color) { paints->writeObject(color, stride * slot); }

    void setOffsets(const std::vector<glm::vec2>& list)
    {
        offsets = device->createBuffer({.size = list.size() * sizeof(glm::vec2), .usage = rhi::BufferUsage::Vertex});
        offsets->write(0, std::as_bytes(std::span(list)));
    }

    void bind(const rhi::Pipeline& p, std::uint32_t paint)
    {
        commands->bindPipeline(p);
        commands->bindVertexBuffer(0, *quad);
        commands->bindVertexBuffer(1, *offsets);
        commands->bindUniformBuffer(0, *paints, stride * paint, 16);
    }

    rhi::Image finish()
    {
        commands->endPass();
        device->submit(*commands);
        return rhi::readTexture(*device, *target);
    }

    std::unique_ptr<rhi::Shader> vertex, fragment;
    std::uint64_t stride = 256;
    std::unique_ptr<rhi::Buffer> paints, quad, offsets;
    std::unique_ptr<rhi::Texture> target;
    std::unique_ptr<rhi::Framebuffer> framebuffer;
    std::unique_ptr<rhi::CommandList> commands;
};

// Shadow atlases render tile by tile: viewport y counts rows from the top on every backend.
TEST_F(DrawStateTest, ViewportPerDrawFillsAtlasTiles)
{
    auto p = pipeline();
    const glm::vec4 tileColors[4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    for (std::uint32_t i = 0; i < 4; ++i)
        setPaint(i, tileColors[i]);
    commands->beginPass({.framebuffer = framebuffer.get()});
    for (std::uint32_t tile = 0; tile < 4; ++tile) {
        const float half = kSize / 2.0f;
        commands->setViewport({(tile % 2) * half, (tile / 2) * half, half, half});
        bind(*p, tile);
        commands->draw(3);
    }
    const rhi::Image image = finish();
    const std::string picture = savePicture(image, configuration() + "/atlas-tiles");
    const Rgba expected[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
    for (std::uint32_t tile = 0; tile < 4; ++tile) {
        const std::uint32_t x = (tile % 2) * kSize / 2 + 5, y = (tile / 2) * kSize / 2 + 5;
        EXPECT_EQ(pixel(image, x, y), expected[tile]) << "tile " << tile << " in " << picture;
    }
}

TEST_F(DrawStateTest, ScissorClipsTheDraw)
{
    auto p = pipeline();
    setPaint(0, {1, 1, 1, 1});
    commands->beginPass({.framebuffer = framebuffer.get()});
    commands->setScissor({8, 4, 16, 8});
    bind(*p, 0);
    commands->draw(3);
    const rhi::Image image = finish();
    int inside = 0, outside = 0;
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            const bool lit = pixel(image, x, y)[0] == 255;
            const bool inScissor = x >= 8 && x < 24 && y >= 4 && y < 12;
            (inScissor ? inside : outside) += lit == inScissor ? 0 : 1;
        }
    EXPECT_EQ(inside, 0) << "unlit pixels inside the scissor";
    EXPECT_EQ(outside, 0) << "lit pixels outside the scissor";
}

TEST_F(DrawStateTest, ColorWriteMaskKeepsMaskedChannels)
{
    auto p = pipeline({.format = rhi::Format::RGBA8, .writeMask = rhi::ColorMask::R | rhi::ColorMask::A});
    setPaint(0, {1, 1, 1, 1});
    commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = glm::vec4(0, 0, 1, 1)});
    bind(*p, 0);
    commands->draw(3);
    EXPECT_EQ(pixel(finish(), 2, kSize - 3), (Rgba{255, 0, 255, 255}));
}

TEST_F(DrawStateTest, AlphaBlendingMixesWithTheTarget)
{
    auto p = pipeline({.format = rhi::Format::RGBA8,
                       .blend = {.enable = true,
                                 .srcColor = rhi::BlendFactor::SrcAlpha,
                                 .dstColor = rhi::BlendFactor::OneMinusSrcAlpha,
                                 .srcAlpha = rhi::BlendFactor::One,
                                 .dstAlpha = rhi::BlendFactor::Zero}});
    setPaint(0, {1, 0, 0, 0.2f}); // 0.2 * 255 = 51 exactly
    commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = glm::vec4(0, 0, 1, 1)});
    bind(*p, 0);
    commands->draw(3);
    const Rgba blended = pixel(finish(), 2, kSize - 3);
    EXPECT_EQ(blended[0], 51);
    EXPECT_EQ(blended[1], 0);
    EXPECT_EQ(blended[2], 204);
    EXPECT_EQ(blended[3], 51);
}

TEST_F(DrawStateTest, InstancedIndexedDrawsPlaceEveryInstance)
{
    // Quarter-size quads: instance 0 at the top-left quadrant, 1 top-right, 2 bottom-left.
    const glm::vec2 corners[4] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
    quad->write(0, std::as_bytes(std::span(corners)));
    setOffsets({{-0.5f, 0.5f}, {0.5f, 0.5f}, {-0.5f, -0.5f}});
    auto p = pipeline();
    setPaint(0, {1, 1, 1, 1});
    for (rhi::IndexType type : {rhi::IndexType::UInt16, rhi::IndexType::UInt32}) {
        const std::uint16_t indices16[6] = {0, 1, 2, 0, 2, 3};
        const std::uint32_t indices32[6] = {0, 1, 2, 0, 2, 3};
        auto indices = device->createBuffer({.size = sizeof(indices32), .usage = rhi::BufferUsage::Index});
        if (type == rhi::IndexType::UInt16)
            indices->write(0, std::as_bytes(std::span(indices16)));
        else
            indices->write(0, std::as_bytes(std::span(indices32)));
        commands->beginPass({.framebuffer = framebuffer.get()});
        bind(*p, 0);
        commands->bindIndexBuffer(*indices, type);
        commands->drawIndexed(6, 2, 0, 0, 1); // instances 1 and 2 only
        const rhi::Image image = finish();
        const std::string name = type == rhi::IndexType::UInt16 ? "uint16" : "uint32";
        EXPECT_EQ(pixel(image, 16, 16)[0], 0) << name << ": instance 0 was drawn";
        EXPECT_EQ(pixel(image, 48, 16)[0], 255) << name << ": instance 1 is missing";
        EXPECT_EQ(pixel(image, 16, 48)[0], 255) << name << ": instance 2 is missing";
        EXPECT_EQ(pixel(image, 48, 48)[0], 0) << name;
    }
}

} // namespace
} // namespace penumbra::testing
