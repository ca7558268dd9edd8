// Count draws on every configuration, through the device's own count where it has one and through the RHI's
// emulation (DeviceDesc::nativeDrawIndirectCount off) everywhere: four commands each fill one quadrant of a 16x16
// target, a dispatch writes how many are drawn, and both paths must fill the same quadrants.
#include "GpuTesting.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/backends/Registry.hpp"
#include "penumbra/rhi/Image.hpp"

#include <array>
#include <fmt/format.h>

namespace penumbra::testing {
namespace {

const char* const quadVertexGlsl = R"(#version 450
layout(location = 0) in vec2 position;
void main() { gl_Position = vec4(position, 0.5, 1.0); }
)";

const char* const redGlsl = R"(#version 450
layout(location = 0) out vec4 color;
void main() { color = vec4(1.0, 0.0, 0.0, 1.0); }
)";

// Copies the count the host wrote at word 0 to word 1, where the draw reads it: a count the GPU wrote.
const char* const countGlsl = R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Count { uint words[]; } count;
void main() { count.words[1] = count.words[0]; }
)";

using Quadrants = std::array<bool, 4>; // top-left, top-right, bottom-left, bottom-right: red or not

// Command q draws two triangles over quadrant q; `count` of maxDrawCount commands are drawn.
Quadrants drawnQuadrants(rhi::Device& device, std::uint32_t count, std::uint32_t maxDrawCount, bool indexed)
{
    auto color = device.createTexture({.width = 16,
                                       .height = 16,
                                       .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                       .debugName = "color"});
    const rhi::Attachment attachment{color.get(), 0};
    auto target = device.createFramebuffer({.colors = {&attachment, 1}});
    std::vector<float> positions;
    std::vector<std::uint32_t> indices;
    const std::array<std::array<float, 2>, 4> corners{{{-1.0f, 0.0f}, {0.0f, 0.0f}, {-1.0f, -1.0f}, {0.0f, -1.0f}}};
    for (const auto& [x, y] : corners)
        for (const auto& [dx, dy] :
             std::array<std::array<float, 2>, 6>{{{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}}) {
            indices.push_back(std::uint32_t(indices.size()));
            positions.insert(positions.end(), {x + dx, y + dy});
        }
    auto vertices = device.createBuffer(
        {.size = positions.size() * sizeof(float), .usage = rhi::BufferUsage::Vertex, .debugName = "quadrants"});
    vertices->write(0, std::as_bytes(std::span(positions)));
    auto indexBuffer = device.createBuffer(
        {.size = indices.size() * sizeof(std::uint32_t), .usage = rhi::BufferUsage::Index, .debugName = "indices"});
    indexBuffer->write(0, std::as_bytes(std::span(indices)));
    // Four commands after 8 bytes of padding, so the commands' offset is not 0.
    std::vector<std::uint32_t> commands{0, 0};
    for (std::uint32_t q = 0; q < 4; ++q) {
        if (indexed)
            commands.insert(commands.end(), {6, 1, 6 * q, 0, 0});
        else
            commands.insert(commands.end(), {6, 1, 6 * q, 0});
    }
    auto arguments = device.createBuffer({.size = commands.size() * sizeof(std::uint32_t),
                                          .usage = rhi::BufferUsage::Indirect,
                                          .debugName = "commands"});
    arguments->write(0, std::as_bytes(std::span(commands)));
    auto counter = device.createBuffer(
        {.size = 8, .usage = rhi::BufferUsage::Indirect | rhi::BufferUsage::Storage, .debugName = "count"});
    const std::array<std::uint32_t, 2> words{count, 0};
    counter->write(0, std::as_bytes(std::span(words)));

    auto vertex = device.createShader({rhi::ShaderStage::Vertex, quadVertexGlsl, "quadrant.vert"});
    auto fragment = device.createShader({rhi::ShaderStage::Fragment, redGlsl, "quadrant.frag"});
    auto pipeline = device.createPipeline({.vertex = vertex.get(),
                                           .fragment = fragment.get(),
                                           .vertexLayout = {{{.stride = 8}}, {{.format = rhi::VertexFormat::Float2}}},
                                           .colorTargets = {{}},
                                           .debugName = "quadrants"});
    auto countShader = device.createShader({rhi::ShaderStage::Compute, countGlsl, "count.comp"});
    auto writer = device.createComputePipeline({.compute = countShader.get(), .debugName = "count"});

    auto list = device.createCommandList();
    list->bindComputePipeline(*writer);
    list->bindStorageBuffer(0, *counter, 0, 8);
    list->dispatch(1);
    list->beginPass({.framebuffer = target.get(), .clearColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)});
    list->bindPipeline(*pipeline);
    list->bindVertexBuffer(0, *vertices);
    list->bindIndexBuffer(*indexBuffer, rhi::IndexType::UInt32);
    if (indexed)
        list->drawIndexedIndirectCount(*arguments, 8, *counter, 4, maxDrawCount);
    else
        list->drawIndirectCount(*arguments, 8, *counter, 4, maxDrawCount);
    list->endPass();
    device.submit(*list);

    const rhi::Image picture = rhi::readTexture(device, *color);
    Quadrants drawn{};
    for (std::uint32_t q = 0; q < 4; ++q)
        drawn[q] = pixel(picture, 4 + 8 * (q % 2), 4 + 8 * (q / 2))[0] == 255;
    return drawn;
}

struct Case {
    std::uint32_t count;
    std::uint32_t maxDrawCount;
    Quadrants expected;
};
// Fewer than the most, none, and more than the most (the most wins).
const std::array<Case, 3> cases{
    {{2, 4, {true, true, false, false}}, {0, 4, {false, false, false, false}}, {9, 3, {true, true, true, false}}}};

void expectCounted(rhi::Device& device)
{
    for (const Case& c : cases)
        for (const bool indexed : {false, true}) {
            SCOPED_TRACE(
                fmt::format("{} of at most {}, {}", c.count, c.maxDrawCount, indexed ? "indexed" : "not indexed"));
            EXPECT_EQ(drawnQuadrants(device, c.count, c.maxDrawCount, indexed), c.expected);
        }
}

using DrawCountTest = GpuTest;

TEST_F(DrawCountTest, TheCountBoundsTheDraws)
{
    const char* path = device->capabilities().drawIndirectCount ? "the device's count" : "the emulation";
    RecordProperty("path", path);
    SCOPED_TRACE(path);
    expectCounted(*device);
}

TEST_F(DrawCountTest, TheEmulationDrawsWhatTheCountSays)
{
    rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration());
    desc.nativeDrawIndirectCount = false;
    auto emulated = createDevice(desc);
    EXPECT_FALSE(emulated->capabilities().drawIndirectCount);
    expectCounted(*emulated);
    expectNoDebugMessages(*emulated);
}

} // namespace
} // namespace penumbra::testing
