// A pipeline whose creation fails half-way, after the backend made some of its native objects,
// must leave none behind: every native object is owned by an RAII handle (VulkanHandle.hpp,
// GlHandle.hpp). Each check has a control that leaks one object on purpose and is caught.
#include "GpuTesting.hpp"

#include "penumbra/backends/Registry.hpp"
#include "penumbra/opengl/Native.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/vulkan/Native.hpp"

#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

const rhi::ShaderSource vertexSource{rhi::ShaderStage::Vertex, R"(#version 450
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)",
                                     "leak.vert"};
const rhi::ShaderSource fragmentSource{rhi::ShaderStage::Fragment, R"(#version 450
layout(location = 0) out vec4 color;
void main() { color = vec4(1.0); }
)",
                                       "leak.frag"};

// A position-only pipeline whose attribute reads vertex buffer slot 1 of a one-slot layout.
rhi::PipelineDesc badSlotPipeline(const rhi::Shader& vertex, const rhi::Shader& fragment)
{
    rhi::PipelineDesc desc;
    desc.debugName = "bad slot";
    desc.vertex = &vertex;
    desc.fragment = &fragment;
    desc.vertexLayout.buffers = {{.stride = 12}};
    desc.vertexLayout.attributes = {{.location = 0, .format = rhi::VertexFormat::Float3, .offset = 0, .buffer = 1}};
    desc.colorTargets = {{.format = rhi::Format::RGBA8}};
    return desc;
}

// Creation must fail with `text`, the error of the step the test means to break.
template <typename Create>
void expectFailureAt(Create create, const std::string& text)
{
    try {
        create();
        ADD_FAILURE() << "the pipeline was created";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

struct GlCounts {
    int programs = 0;
    int vertexArrays = 0;
};

// Live programs and vertex arrays among the first names; GL hands out small integers, and the
// test creates far fewer objects than this.
GlCounts liveGlObjects(const rhi::Device& device)
{
    opengl::makeCurrent(device);
    const opengl::GlFunctions& gl = opengl::glFunctions(device);
    GlCounts counts;
    for (GLuint name = 1; name < 4096; ++name) {
        counts.programs += gl.IsProgram(name) ? 1 : 0;
        counts.vertexArrays += gl.IsVertexArray(name) ? 1 : 0;
    }
    return counts;
}

// The shaders are created first, so the pipeline's own names are the only ones made in between.
TEST(PipelineLeakTest, OpenGlPipelineFailingAfterLinkLeavesNoProgramOrVertexArray)
{
    // Without the RHI's validation layer, which refuses the bad slot before the backend makes anything.
    rhi::DeviceDesc desc = penumbra::parseConfiguration("opengl");
    desc.validation = true;
    desc.validateUsage = false;
    auto device = createDevice(desc);
    auto vertex = device->createShader(vertexSource);
    auto fragment = device->createShader(fragmentSource);
    const GlCounts before = liveGlObjects(*device);
    // Thrown while building the vertex array, after the program was linked.
    expectFailureAt([&] { device->createPipeline(badSlotPipeline(*vertex, *fragment)); },
                    "reads vertex buffer slot 1, which the layout does not declare");
    const GlCounts after = liveGlObjects(*device);
    EXPECT_EQ(after.programs, before.programs);
    EXPECT_EQ(after.vertexArrays, before.vertexArrays);
    expectNoDebugMessages(*device);
}

TEST(PipelineLeakTest, LeakedGlProgramCatchesFault)
{
    auto device = createValidatedDevice("opengl");
    const GlCounts before = liveGlObjects(*device);
    const opengl::GlFunctions& gl = opengl::glFunctions(*device);
    const GLuint program = gl.CreateProgram();
    GLuint vertexArray = 0;
    gl.CreateVertexArrays(1, &vertexArray);
    const GlCounts after = liveGlObjects(*device);
    EXPECT_EQ(after.programs, before.programs + 1);
    EXPECT_EQ(after.vertexArrays, before.vertexArrays + 1);
    gl.DeleteProgram(program);
    gl.DeleteVertexArrays(1, &vertexArray);
}

// What the Vulkan backend writes to standard error while `use`'s device is destroyed: the
// validation layer's object tracker names every object still alive at vkDestroyDevice.
template <typename Use>
std::string vulkanTeardownReport(Use use)
{
    ::testing::internal::CaptureStderr();
    {
        auto device = createValidatedDevice("vulkan");
        use(*device);
    }
    return ::testing::internal::GetCapturedStderr();
}

// The fragment shader is not a Vulkan one: creation fails after the layout and render pass exist.
TEST(PipelineLeakTest, VulkanPipelineFailingHalfWayLeavesNoObjectAtDeviceDestruction)
{
    auto gl = createValidatedDevice("opengl");
    auto foreignFragment = gl->createShader(fragmentSource);
    const std::string report = vulkanTeardownReport([&](rhi::Device& device) {
        auto vertex = device.createShader(vertexSource);
        rhi::PipelineDesc desc = badSlotPipeline(*vertex, *foreignFragment);
        desc.vertexLayout.attributes.front().buffer = 0;
        expectFailureAt([&] { device.createPipeline(desc); }, "was not created by a Vulkan device");
        expectNoDebugMessages(device);
    });
    EXPECT_EQ(report, "");
}

TEST(PipelineLeakTest, LeakedVulkanObjectCatchesFault)
{
    const std::string report = vulkanTeardownReport([](rhi::Device& device) {
        VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        VkSampler sampler = VK_NULL_HANDLE;
        ASSERT_EQ(vkCreateSampler(vulkan::native(device).device, &info, nullptr, &sampler), VK_SUCCESS);
    });
    EXPECT_NE(report.find("VkSampler"), std::string::npos) << report;
}

} // namespace
} // namespace penumbra::testing
