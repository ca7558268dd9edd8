// Instances culled in compute and drawn indirectly: 1024 squares on a grid, a dispatch keeps those whose centre lies
// inside a circle (the "view"), appends their offsets to a storage buffer and counts them in an indirect draw command,
// and one drawIndirectCount draws the survivors, the instance count and the draw count read on the GPU. The number of
// survivors is checked against the CPU's. The compute-to-draw hazards (storage written, then read as vertices and as
// indirect arguments) are the RHI's to order. Writes compute_cull.png.
#include "ExampleSupport.hpp"

#include <penumbra/backends/CreateDevice.hpp>
#include <penumbra/rhi/Image.hpp>

#include <array>
#include <glm/vec4.hpp>
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

using namespace penumbra;

namespace {

constexpr std::uint32_t kSize = 128;
constexpr std::uint32_t kSide = 32; // instances per row
constexpr float kRadius = 0.8f; // of the circle instances are kept in, in NDC

// One invocation per instance: the kept ones are appended to `kept` and counted in the draw command.
const char* const cullGlsl = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Instances { vec2 offsets[]; } instances;
layout(std430, binding = 1) writeonly buffer Kept { vec2 offsets[]; } kept;
layout(std430, binding = 2) buffer Draw { uint vertexCount; uint instanceCount; uint firstVertex; uint firstInstance; } draw;
layout(std430, binding = 3) writeonly buffer DrawCount { uint count; } drawCount;
const float radius = 0.8;
void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= instances.offsets.length() || length(instances.offsets[i]) > radius)
        return;
    uint slot = atomicAdd(draw.instanceCount, 1u);
    kept.offsets[slot] = instances.offsets[i];
    if (slot == 0u)
        drawCount.count = 1u;
}
)";

// A small square per instance, placed by its per-instance offset.
const char* const vertexGlsl = R"(#version 450
layout(location = 0) in vec2 offset;
layout(location = 0) out vec2 position;
const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
void main()
{
    position = offset;
    gl_Position = vec4(offset + 0.022 * corners[gl_VertexIndex], 0.5, 1.0);
}
)";

const char* const fragmentGlsl = R"(#version 450
layout(location = 0) in vec2 position;
layout(location = 0) out vec4 color;
void main() { color = vec4(0.5 + 0.5 * position, 0.8, 1.0); }
)";

struct DrawCommand {
    std::uint32_t vertexCount, instanceCount, firstVertex, firstInstance;
};

} // namespace

int main(int argc, char** argv)
{
    auto device = createDevice(examples::backendArgument(argc, argv));
    std::vector<std::array<float, 2>> offsets;
    std::uint32_t inside = 0;
    for (std::uint32_t y = 0; y < kSide; ++y)
        for (std::uint32_t x = 0; x < kSide; ++x) {
            const float u = -1.0f + (2.0f * float(x) + 1.0f) / kSide, v = -1.0f + (2.0f * float(y) + 1.0f) / kSide;
            offsets.push_back({u, v});
            inside += std::sqrt(u * u + v * v) <= kRadius ? 1 : 0;
        }
    const std::uint64_t bytes = offsets.size() * sizeof(offsets[0]);
    auto instances = device->createBuffer({.size = bytes, .usage = rhi::BufferUsage::Storage});
    instances->write(0, std::as_bytes(std::span(offsets)));
    auto kept = device->createBuffer({.size = bytes, .usage = rhi::BufferUsage::Storage | rhi::BufferUsage::Vertex});
    auto draw = device->createBuffer(
        {.size = sizeof(DrawCommand), .usage = rhi::BufferUsage::Storage | rhi::BufferUsage::Indirect});
    draw->writeObject(DrawCommand{6, 0, 0, 0});
    auto drawCount = device->createBuffer(
        {.size = sizeof(std::uint32_t), .usage = rhi::BufferUsage::Storage | rhi::BufferUsage::Indirect});
    drawCount->writeObject(std::uint32_t{0});

    auto cullShader = device->createShader({rhi::ShaderStage::Compute, cullGlsl, "cull.comp"});
    auto cull = device->createComputePipeline({.compute = cullShader.get(), .debugName = "cull"});
    auto vertex = device->createShader({rhi::ShaderStage::Vertex, vertexGlsl, "squares.vert"});
    auto fragment = device->createShader({rhi::ShaderStage::Fragment, fragmentGlsl, "squares.frag"});
    auto squares =
        device->createPipeline({.vertex = vertex.get(),
                                .fragment = fragment.get(),
                                .vertexLayout = {{{sizeof(offsets[0]), true}}, {{0, rhi::VertexFormat::Float2, 0, 0}}},
                                .colorTargets = {{}}});
    auto picture = device->createTexture({.width = kSize, .height = kSize, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment attachment{picture.get(), 0};
    auto target = device->createFramebuffer({.colors = {&attachment, 1}});

    auto commands = device->createCommandList();
    commands->bindComputePipeline(*cull);
    commands->bindStorageBuffer(0, *instances, 0, bytes);
    commands->bindStorageBuffer(1, *kept, 0, bytes);
    commands->bindStorageBuffer(2, *draw, 0, sizeof(DrawCommand));
    commands->bindStorageBuffer(3, *drawCount, 0, sizeof(std::uint32_t));
    commands->dispatch(std::uint32_t(offsets.size()) / cull->workgroupSize()[0]);
    commands->beginPass({.framebuffer = target.get(), .clearColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)});
    commands->bindPipeline(*squares);
    commands->bindVertexBuffer(0, *kept);
    commands->drawIndirectCount(*draw, 0, *drawCount, 0, 1);
    commands->endPass();
    device->submit(*commands);

    DrawCommand drawn{};
    draw->read(0, std::as_writable_bytes(std::span(&drawn, 1)));
    if (drawn.instanceCount != inside) {
        std::fprintf(stderr, "compute_cull: the GPU kept %u instances, the CPU %u\n", drawn.instanceCount, inside);
        return 1;
    }
    examples::writePng("compute_cull.png", rhi::readTexture(*device, *picture));
    std::printf("compute_cull: %u of %zu instances kept and drawn indirectly, as the CPU counts\n", inside,
                offsets.size());
    return 0;
}
