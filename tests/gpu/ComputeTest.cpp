// Compute on every configuration: pipelines from GLSL compute shaders, storage buffers and images, indirect
// dispatches and draws, each checked against the CPU. Every scene is a write followed by a read of another kind,
// so with synchronization validation on (and any message failing the test) each also shows that the barriers the
// RHI derives are enough; HazardTest shows that each one is needed.
#include "ComputeScenes.hpp"
#include "GpuTesting.hpp"

#include <numeric>

namespace penumbra::testing {
namespace {

using ComputeTest = GpuTest;

TEST_F(ComputeTest, TheWorkgroupSizeAndSharedMemoryComeFromReflection)
{
    auto shader = device->createShader({rhi::ShaderStage::Compute, R"(#version 450
        layout(local_size_x = 8, local_size_y = 4, local_size_z = 2) in;
        shared vec4 tile[8][4];
        shared uint count;
        layout(std430, binding = 3) buffer Out { uint values[]; } outputs;
        void main() { tile[gl_LocalInvocationID.x][gl_LocalInvocationID.y] = vec4(1.0); count = 1u;
                      outputs.values[gl_LocalInvocationIndex] = count; })",
                                        "reflect.comp"});
    EXPECT_EQ(shader->compiled().workgroupSize, (std::array<std::uint32_t, 3>{8, 4, 2}));
    EXPECT_EQ(shader->compiled().sharedMemoryBytes, 8u * 4u * 16u + 4u);
    auto pipeline = device->createComputePipeline({.compute = shader.get(), .debugName = "reflect"});
    ASSERT_EQ(pipeline->bindings().size(), 1u);
    EXPECT_EQ(pipeline->bindings()[0].kind, rhi::BindingKind::StorageBuffer);
    EXPECT_TRUE(pipeline->bindings()[0].writes);
    EXPECT_EQ(pipeline->workgroupSize(), (std::array<std::uint32_t, 3>{8, 4, 2}));
}

TEST_F(ComputeTest, TheLimitsAreReported)
{
    const rhi::Capabilities& caps = device->capabilities();
    // GL 4.5 Table 23.64 and Vulkan 1.3 Table 53 require at least these.
    EXPECT_GE(caps.maxWorkgroupInvocations, 128u);
    EXPECT_GE(caps.maxWorkgroupSize[0], 128u);
    EXPECT_GE(caps.maxWorkgroupCount[0], 65535u);
    EXPECT_GE(caps.maxComputeSharedMemory, 16384u);
    EXPECT_GE(caps.maxStorageBufferRange, 1u << 24);
    EXPECT_TRUE(caps.format(rhi::Format::RGBA8).storage);
    EXPECT_FALSE(caps.format(rhi::Format::D32F).storage);
    EXPECT_FALSE(caps.format(rhi::Format::RGBA8_SRGB).storage); // no sRGB image formats in GL or Vulkan
}

TEST_F(ComputeTest, PrefixSumMatchesTheCpu)
{
    std::vector<std::uint32_t> values(1000);
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = std::uint32_t((i * 7919u) % 1013u);
    std::vector<std::uint32_t> expected(values.size());
    std::inclusive_scan(values.begin(), values.end(), expected.begin());
    EXPECT_EQ(prefixSum(*device, values), expected);
}

TEST_F(ComputeTest, HistogramOfARenderedPictureMatchesTheCpu)
{
    const Histogram histogram = pictureHistogram(*device);
    std::array<std::uint32_t, 256> expected{};
    for (std::uint8_t red : histogram.red)
        ++expected[red];
    EXPECT_EQ(histogram.total, 32u * 32u);
    EXPECT_EQ(histogram.bins, expected);
    // A ramp, not a flat picture: a histogram of one bin would pass with the dispatch reading nothing rendered.
    EXPECT_GE(std::count_if(expected.begin(), expected.end(), [](std::uint32_t n) { return n > 0; }), 16);
}

TEST_F(ComputeTest, ADrawReadsVerticesAndArgumentsADispatchWrote)
{
    for (bool indirect : {false, true}) {
        SCOPED_TRACE(indirect ? "drawIndirect" : "draw");
        const std::vector<std::uint8_t> red = computedTriangle(*device, indirect);
        EXPECT_EQ(red[8 * 16 + 8], 255); // the centre is inside the triangle
        EXPECT_EQ(red[0], 0); // a corner is not
    }
}

TEST_F(ComputeTest, DispatchIndirectRunsTheWorkgroupsADispatchWrote)
{
    EXPECT_EQ(indirectInvocations(*device), 5u * 4u);
}

TEST_F(ComputeTest, AStorageImageIsStoredLoadedAndReadBack)
{
    const ImageSum sum = storageImageSum(*device);
    EXPECT_EQ(sum.red, 16u * (15u * 16u / 2u)); // each row holds red 0..15
    ASSERT_EQ(sum.image.size(), 256u);
    for (std::uint32_t i = 0; i < 256; ++i)
        ASSERT_EQ(sum.image[i], i % 16) << "texel " << i;
}

} // namespace
} // namespace penumbra::testing
