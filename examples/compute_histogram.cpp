// A histogram of a rendered picture, on the GPU: a pass renders colour rings into a texture, a compute dispatch
// samples every texel and counts its red value in a 256-bin storage buffer with atomics, and the counts are checked
// against the CPU's count of the read-back picture. The render-target-to-compute and compute-to-host hazards are the
// RHI's to order; nothing here names a barrier. Writes compute_histogram.png: the picture above its histogram.
#include "ExampleSupport.hpp"

#include <penumbra/backends/CreateDevice.hpp>
#include <penumbra/rhi/Image.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <span>

using namespace penumbra;

namespace {

constexpr std::uint32_t kSize = 128;

const char* const vertexGlsl = R"(#version 450
const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
layout(location = 0) out vec2 position;
void main()
{
    gl_Position = vec4(corners[gl_VertexIndex], 0.5, 1.0);
    position = corners[gl_VertexIndex];
}
)";

const char* const fragmentGlsl = R"(#version 450
layout(location = 0) in vec2 position;
layout(location = 0) out vec4 color;
void main()
{
    float rings = 0.5 + 0.5 * cos(12.0 * length(position));
    color = vec4(rings * (0.6 + 0.4 * position.x), 0.3, 0.6, 1.0);
}
)";

// One invocation per texel; bins[red] counts the texels of each red value.
const char* const histogramGlsl = R"(#version 450
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D picture;
layout(std430, binding = 1) buffer Histogram { uint bins[256]; } histogram;
void main()
{
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, textureSize(picture, 0))))
        return;
    atomicAdd(histogram.bins[uint(round(texelFetch(picture, texel, 0).r * 255.0))], 1u);
}
)";

using Bins = std::array<std::uint32_t, 256>;

// The picture with the histogram drawn under it as white bars on black, each bin one column wide.
rhi::Image withBars(const rhi::Image& picture, const Bins& bins)
{
    constexpr std::uint32_t barHeight = 64;
    rhi::Image out{256, kSize + barHeight, rhi::Format::RGBA8, {}};
    out.bytes.assign(std::size_t(out.width) * out.height * 4, std::byte{0});
    for (std::size_t i = 3; i < out.bytes.size(); i += 4)
        out.bytes[i] = std::byte{255}; // opaque black
    for (std::uint32_t y = 0; y < kSize; ++y)
        std::copy_n(picture.texel(0, y), kSize * 4, out.bytes.data() + std::size_t(y) * out.width * 4);
    const std::uint32_t tallest = std::max(*std::max_element(bins.begin(), bins.end()), 1u);
    for (std::uint32_t bin = 0; bin < 256; ++bin)
        for (std::uint32_t h = 0; h < bins[bin] * barHeight / tallest; ++h)
            std::fill_n(out.bytes.data() + (std::size_t(out.height - 1 - h) * out.width + bin) * 4, 4, std::byte{255});
    return out;
}

} // namespace

int main(int argc, char** argv)
{
    auto device = createDevice(examples::backendArgument(argc, argv));
    auto picture = device->createTexture(
        {.width = kSize, .height = kSize, .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled});
    const rhi::Attachment attachment{picture.get(), 0};
    auto target = device->createFramebuffer({.colors = {&attachment, 1}});
    auto vertex = device->createShader({rhi::ShaderStage::Vertex, vertexGlsl, "rings.vert"});
    auto fragment = device->createShader({rhi::ShaderStage::Fragment, fragmentGlsl, "rings.frag"});
    auto rings = device->createPipeline({.vertex = vertex.get(), .fragment = fragment.get(), .colorTargets = {{}}});
    auto compute = device->createShader({rhi::ShaderStage::Compute, histogramGlsl, "histogram.comp"});
    // The storage block's std430 layout is checked against the C++ array it is read into.
    auto histogram = device->createComputePipeline(
        {.compute = compute.get(), .storageLayouts = {{"Histogram", sizeof(Bins), {{"bins", 0, sizeof(Bins)}}}}});
    auto nearest = device->createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});
    auto counts = device->createBuffer({.size = sizeof(Bins), .usage = rhi::BufferUsage::Storage});
    counts->writeObject(Bins{});

    auto commands = device->createCommandList();
    commands->pushLabel("rings");
    commands->beginPass({.framebuffer = target.get()});
    commands->bindPipeline(*rings);
    commands->draw(3);
    commands->endPass();
    commands->popLabel();
    commands->pushLabel("histogram");
    commands->bindComputePipeline(*histogram);
    commands->bindTexture(0, *picture, *nearest);
    commands->bindStorageBuffer(1, *counts, 0, sizeof(Bins));
    const auto& size = histogram->workgroupSize(); // 16 x 16, from the shader
    commands->dispatch((kSize + size[0] - 1) / size[0], (kSize + size[1] - 1) / size[1]);
    commands->popLabel();
    device->submit(*commands);

    Bins gpu{};
    counts->read(0, std::as_writable_bytes(std::span(gpu)));
    const rhi::Image image = rhi::readTexture(*device, *picture);
    Bins cpu{};
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x)
            ++cpu[std::size_t(image.texel(x, y)[0])];
    if (gpu != cpu) {
        std::fprintf(stderr, "compute_histogram: the GPU's histogram differs from the CPU's\n");
        return 1;
    }
    examples::writePng("compute_histogram.png", withBars(image, gpu));
    std::printf("compute_histogram: %u texels in 256 bins, equal to the CPU's count\n", kSize * kSize);
    return 0;
}
