#include "ComputeScenes.hpp"

#include "penumbra/rhi/Image.hpp"
#include "penumbra/rhi/ValidatingDevice.hpp"

#include <cstddef>
#include <span>

namespace penumbra::testing {
namespace {

const char* const prefixSumGlsl = R"(#version 450
layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly buffer Input { uint values[]; } inputs;
layout(std430, binding = 1) writeonly buffer Output { uint sums[]; } outputs;
shared uint partial[256];
void main()
{
    // Each invocation scans four values, the workgroup scans the 256 partial sums (Hillis and Steele, 1986).
    uint i = gl_LocalInvocationID.x;
    uint base = i * 4u;
    uint local[4];
    uint running = 0u;
    for (uint k = 0u; k < 4u; ++k) {
        running += inputs.values[base + k];
        local[k] = running;
    }
    partial[i] = running;
    barrier();
    for (uint offset = 1u; offset < 256u; offset *= 2u) {
        uint add = i >= offset ? partial[i - offset] : 0u;
        barrier();
        partial[i] += add;
        barrier();
    }
    uint before = i == 0u ? 0u : partial[i - 1u];
    for (uint k = 0u; k < 4u; ++k)
        outputs.sums[base + k] = before + local[k];
}
)";

const char* const rampVertexGlsl = R"(#version 450
const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
layout(location = 0) out float ramp;
void main()
{
    gl_Position = vec4(corners[gl_VertexIndex], 0.5, 1.0);
    ramp = corners[gl_VertexIndex].x * 0.5 + 0.5;
}
)";

const char* const rampFragmentGlsl = R"(#version 450
layout(location = 0) in float ramp;
layout(location = 0) out vec4 color;
void main() { color = vec4(ramp, 0.25, 0.0, 1.0); }
)";

const char* const histogramGlsl = R"(#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D picture;
layout(std430, binding = 1) buffer Histogram { uint total; uint bins[]; } histogram;
void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(picture, 0);
    if (p.x >= size.x || p.y >= size.y)
        return;
    uint red = uint(round(texelFetch(picture, p, 0).r * 255.0));
    atomicAdd(histogram.bins[red], 1u);
    atomicAdd(histogram.total, 1u);
}
)";

const char* const triangleWriterGlsl = R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Vertices { vec4 positions[3]; } vertices;
layout(std430, binding = 1) writeonly buffer Arguments {
    uint vertexCount;
    uint instanceCount;
    uint firstVertex;
    uint firstInstance;
} arguments;
void main()
{
    vertices.positions[0] = vec4(-0.5, -0.5, 0.5, 1.0);
    vertices.positions[1] = vec4(0.5, -0.5, 0.5, 1.0);
    vertices.positions[2] = vec4(0.0, 0.5, 0.5, 1.0);
    arguments.vertexCount = 3u;
    arguments.instanceCount = 1u;
    arguments.firstVertex = 0u;
    arguments.firstInstance = 0u;
}
)";

const char* const positionVertexGlsl = R"(#version 450
layout(location = 0) in vec4 position;
void main() { gl_Position = position; }
)";

const char* const redFragmentGlsl = R"(#version 450
layout(location = 0) out vec4 color;
void main() { color = vec4(1.0, 0.0, 0.0, 1.0); }
)";

const char* const argumentsWriterGlsl = R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Arguments { uint x; uint y; uint z; } arguments;
void main()
{
    arguments.x = 5u;
    arguments.y = 1u;
    arguments.z = 1u;
}
)";

const char* const counterGlsl = R"(#version 450
layout(local_size_x = 4) in;
layout(std430, binding = 1) buffer Counter { uint invocations; } counter;
void main() { atomicAdd(counter.invocations, 1u); }
)";

const char* const imageWriterGlsl = R"(#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba8) writeonly uniform image2D image;
void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    imageStore(image, p, vec4(float(p.x) / 255.0, float(p.y) / 255.0, 0.0, 1.0));
}
)";

const char* const imageReaderGlsl = R"(#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba8) readonly uniform image2D image;
layout(std430, binding = 1) buffer Sum { uint red; } sum;
void main() { atomicAdd(sum.red, uint(round(imageLoad(image, ivec2(gl_GlobalInvocationID.xy)).r * 255.0))); }
)";

std::unique_ptr<rhi::ComputePipeline> computePipeline(rhi::Device& device, const char* glsl, const char* name,
                                                      std::vector<rhi::UniformLayout> storageLayouts = {},
                                                      std::vector<const rhi::BindingSetLayout*> bindingSetLayouts = {})
{
    auto shader = device.createShader({rhi::ShaderStage::Compute, glsl, name});
    return device.createComputePipeline({.compute = shader.get(),
                                         .storageLayouts = std::move(storageLayouts),
                                         .bindingSetLayouts = std::move(bindingSetLayouts),
                                         .debugName = name});
}

std::unique_ptr<rhi::CommandList> commandList(rhi::Device& device, const SceneOptions& options)
{
    auto list = device.createCommandList();
    dynamic_cast<rhi::ValidatingCommandList&>(*list).setBarriersSuppressed(options.suppressBarriers);
    return list;
}

template <typename T>
std::vector<T> readAll(const rhi::Buffer& buffer)
{
    std::vector<T> values(buffer.desc().size / sizeof(T));
    buffer.read(0, std::as_writable_bytes(std::span(values)));
    return values;
}

std::vector<std::uint8_t> redBytes(const rhi::Image& image)
{
    std::vector<std::uint8_t> red;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            red.push_back(std::uint8_t(image.texel(x, y)[0]));
    return red;
}

} // namespace

std::vector<std::uint32_t> prefixSum(rhi::Device& device, const std::vector<std::uint32_t>& values,
                                     const SceneOptions& options)
{
    const std::uint64_t bytes = 1024 * sizeof(std::uint32_t);
    auto input = device.createBuffer({.size = bytes, .usage = rhi::BufferUsage::Storage, .debugName = "input"});
    auto output = device.createBuffer({.size = bytes, .usage = rhi::BufferUsage::Storage, .debugName = "output"});
    auto readback = device.createBuffer({.size = bytes, .usage = rhi::BufferUsage::Readback, .debugName = "readback"});
    std::vector<std::uint32_t> padded(values);
    padded.resize(1024, 0);
    input->write(0, std::as_bytes(std::span(padded)));
    // A runtime array alone: the block is its element, at offset 0.
    auto pipeline = computePipeline(device, prefixSumGlsl, "prefix_sum.comp",
                                    {{"Output", 0, {{"sums", 0, sizeof(std::uint32_t)}}}});
    auto list = commandList(device, options);
    list->pushLabel("prefix sum");
    list->bindComputePipeline(*pipeline);
    list->bindStorageBuffer(0, *input, 0, bytes);
    list->bindStorageBuffer(1, *output, 0, bytes);
    list->dispatch(1);
    list->insertLabel("read back");
    list->copyBuffer(*output, 0, *readback, 0, bytes);
    list->popLabel();
    device.submit(*list);
    std::vector<std::uint32_t> sums = readAll<std::uint32_t>(*readback);
    sums.resize(values.size());
    return sums;
}

Histogram pictureHistogram(rhi::Device& device, const SceneOptions& options)
{
    auto picture = device.createTexture({.width = 32,
                                         .height = 32,
                                         .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                         .debugName = "picture"});
    const rhi::Attachment attachment{picture.get(), 0};
    auto target = device.createFramebuffer({.colors = {&attachment, 1}});
    auto vertex = device.createShader({rhi::ShaderStage::Vertex, rampVertexGlsl, "ramp.vert"});
    auto fragment = device.createShader({rhi::ShaderStage::Fragment, rampFragmentGlsl, "ramp.frag"});
    auto draw = device.createPipeline(
        {.vertex = vertex.get(), .fragment = fragment.get(), .colorTargets = {{}}, .debugName = "ramp"});
    struct HistogramHeader {
        std::uint32_t total;
    };
    auto histogram = computePipeline(device, histogramGlsl, "histogram.comp",
                                     {{"Histogram",
                                       sizeof(HistogramHeader),
                                       {PENUMBRA_UNIFORM_MEMBER(HistogramHeader, total),
                                        PENUMBRA_UNIFORM_ARRAY_ELEMENT(HistogramHeader, bins, std::uint32_t)}}});
    auto sampler = device.createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});
    const std::uint64_t bytes = sizeof(Histogram::total) + sizeof(Histogram::bins);
    auto counts = device.createBuffer({.size = bytes, .usage = rhi::BufferUsage::Storage, .debugName = "histogram"});
    counts->write(0, std::vector<std::byte>(bytes));

    auto list = commandList(device, options);
    list->beginPass({.framebuffer = target.get()});
    list->bindPipeline(*draw);
    list->draw(3);
    list->endPass();
    list->bindComputePipeline(*histogram);
    list->bindTexture(0, *picture, *sampler);
    list->bindStorageBuffer(1, *counts, 0, bytes);
    list->dispatch(4, 4);
    device.submit(*list);

    Histogram result;
    counts->read(0, std::as_writable_bytes(std::span(&result.total, 1)));
    counts->read(sizeof(result.total), std::as_writable_bytes(std::span(result.bins)));
    result.red = redBytes(rhi::readTexture(device, *picture));
    return result;
}

std::vector<std::uint8_t> computedTriangle(rhi::Device& device, bool indirect, const SceneOptions& options)
{
    auto color = device.createTexture({.width = 16,
                                       .height = 16,
                                       .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                       .debugName = "color"});
    const rhi::Attachment attachment{color.get(), 0};
    auto target = device.createFramebuffer({.colors = {&attachment, 1}});
    auto vertices = device.createBuffer(
        {.size = 48, .usage = rhi::BufferUsage::Vertex | rhi::BufferUsage::Storage, .debugName = "vertices"});
    auto arguments = device.createBuffer(
        {.size = 16, .usage = rhi::BufferUsage::Indirect | rhi::BufferUsage::Storage, .debugName = "arguments"});
    auto writer = computePipeline(device, triangleWriterGlsl, "triangle_writer.comp");
    auto vertex = device.createShader({rhi::ShaderStage::Vertex, positionVertexGlsl, "position.vert"});
    auto fragment = device.createShader({rhi::ShaderStage::Fragment, redFragmentGlsl, "red.frag"});
    auto draw = device.createPipeline({.vertex = vertex.get(),
                                       .fragment = fragment.get(),
                                       .vertexLayout = {{{.stride = 16}}, {{.format = rhi::VertexFormat::Float4}}},
                                       .colorTargets = {{}},
                                       .debugName = "computed triangle"});

    auto list = commandList(device, options);
    list->bindComputePipeline(*writer);
    list->bindStorageBuffer(0, *vertices, 0, 48);
    list->bindStorageBuffer(1, *arguments, 0, 16);
    list->dispatch(1);
    list->beginPass({.framebuffer = target.get(), .clearColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)});
    list->bindPipeline(*draw);
    list->bindVertexBuffer(0, *vertices);
    if (indirect)
        list->drawIndirect(*arguments);
    else
        list->draw(3);
    list->endPass();
    device.submit(*list);
    return redBytes(rhi::readTexture(device, *color));
}

std::uint32_t indirectInvocations(rhi::Device& device, const SceneOptions& options)
{
    auto arguments = device.createBuffer(
        {.size = 12, .usage = rhi::BufferUsage::Indirect | rhi::BufferUsage::Storage, .debugName = "arguments"});
    auto counter = device.createBuffer({.size = 4, .usage = rhi::BufferUsage::Storage, .debugName = "counter"});
    counter->writeObject(std::uint32_t(0));
    auto writer = computePipeline(device, argumentsWriterGlsl, "arguments_writer.comp");
    auto counting = computePipeline(device, counterGlsl, "counter.comp");
    auto list = commandList(device, options);
    list->bindComputePipeline(*writer);
    list->bindStorageBuffer(0, *arguments, 0, 12);
    list->dispatch(1);
    list->bindComputePipeline(*counting);
    list->bindStorageBuffer(1, *counter, 0, 4);
    list->dispatchIndirect(*arguments);
    device.submit(*list);
    return readAll<std::uint32_t>(*counter).front();
}

ImageSum storageImageSum(rhi::Device& device, const SceneOptions& options)
{
    auto image = device.createTexture(
        {.width = 16, .height = 16, .usage = rhi::TextureUsage::Storage, .debugName = "storage image"});
    auto sum = device.createBuffer({.size = 4, .usage = rhi::BufferUsage::Storage, .debugName = "sum"});
    sum->writeObject(std::uint32_t(0));
    auto readback = device.createBuffer({.size = 16 * 16 * 4, .usage = rhi::BufferUsage::Readback});
    auto layout = device.createBindingSetLayout(
        {.items = {{0, rhi::BindingKind::StorageTexture}, {1, rhi::BindingKind::StorageBuffer}}, .debugName = "sum"});
    std::vector<const rhi::BindingSetLayout*> listed;
    if (options.listedLayout)
        listed.push_back(layout.get());
    auto writer = computePipeline(device, imageWriterGlsl, "image_writer.comp", {}, listed);
    auto reader = computePipeline(device, imageReaderGlsl, "image_reader.comp", {}, listed);
    auto set = device.createBindingSet(
        {.layout = layout.get(),
         .items = {rhi::BindingSetItem::storageTexture(0, *image), rhi::BindingSetItem::storageBuffer(1, *sum, 0, 4)},
         .debugName = "sum"});
    auto list = commandList(device, options);
    if (options.bindingSet) {
        list->bindBindingSet(*set);
    } else {
        list->bindStorageTexture(0, *image);
        list->bindStorageBuffer(1, *sum, 0, 4);
    }
    list->bindComputePipeline(*writer);
    list->dispatch(2, 2);
    list->bindComputePipeline(*reader);
    list->dispatch(2, 2);
    list->copyTextureToBuffer(*image, 0, 0, *readback);
    device.submit(*list);
    ImageSum result{readAll<std::uint32_t>(*sum).front(), {}};
    for (std::uint32_t texel : readAll<std::uint32_t>(*readback))
        result.image.push_back(std::uint8_t(texel & 0xffu));
    return result;
}

} // namespace penumbra::testing
