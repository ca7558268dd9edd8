// On Vulkan a binding set is a descriptor set of its own, written once when the set is created: a pipeline that lists
// its layout (PipelineDesc::bindingSetLayouts) has it bound with one vkCmdBindDescriptorSets, however many draws and
// pipeline changes follow. The backend's counts of its descriptor calls tell that path from the per-draw one.
#include "GpuTesting.hpp"
#include "TintedImageShaders.hpp"

#include "penumbra/vulkan/Native.hpp"

#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

// Four draws with a set of the tint and the image bound once, switching between two pipelines (culled or not) that
// list its layout when `listed`; returns the list's counts.
vulkan::DescriptorCounts countFourDraws(bool listed)
{
    auto device = createValidatedDevice("vulkan");
    auto picture = device->createTexture({.width = 4, .height = 4, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment attachment{picture.get(), 0};
    auto target = device->createFramebuffer({.colors = {&attachment, 1}});
    auto image = device->createTexture({.width = 1, .height = 1, .debugName = "image"});
    auto sampler = device->createSampler({});
    auto tint = device->createBuffer({.size = 16, .usage = rhi::BufferUsage::Uniform, .debugName = "tint"});
    tint->writeObject(std::array<float, 4>{1.0f, 1.0f, 1.0f, 1.0f});
    auto vertex = device->createShader({rhi::ShaderStage::Vertex, kTintedImageVertexGlsl, "calls.vert"});
    auto fragment = device->createShader({rhi::ShaderStage::Fragment, kTintedImageFragmentGlsl, "calls.frag"});
    auto layout = device->createBindingSetLayout(
        {.items = {{0, rhi::BindingKind::UniformBuffer}, {1, rhi::BindingKind::SampledTexture}}, .debugName = "set"});
    auto set = device->createBindingSet({.layout = layout.get(),
                                         .items = {rhi::BindingSetItem::uniformBuffer(0, *tint, 0, 16),
                                                   rhi::BindingSetItem::sampledTexture(1, *image, *sampler)},
                                         .debugName = "set"});
    std::array<std::unique_ptr<rhi::Pipeline>, 2> pipelines;
    for (rhi::CullMode cull : {rhi::CullMode::None, rhi::CullMode::Back}) {
        rhi::PipelineDesc desc{.vertex = vertex.get(), .fragment = fragment.get(), .cull = cull, .colorTargets = {{}}};
        if (listed)
            desc.bindingSetLayouts = {layout.get()};
        pipelines[cull == rhi::CullMode::Back ? 1 : 0] = device->createPipeline(desc);
    }
    auto list = device->createCommandList();
    list->beginPass({.framebuffer = target.get()});
    list->bindBindingSet(*set);
    for (int draw = 0; draw < 4; ++draw) {
        list->bindPipeline(*pipelines[draw % 2]);
        list->draw(3);
    }
    list->endPass();
    const vulkan::DescriptorCounts counts = vulkan::descriptorCounts(*list);
    device->submit(*list);
    expectNoDebugMessages(*device);
    return counts;
}

TEST(BindingSetCallsTest, AListedSetIsBoundWithOneCallAndNeverWrittenWhileRecording)
{
    const vulkan::DescriptorCounts counts = countFourDraws(true);
    EXPECT_EQ(counts.bindCalls, 1u);
    EXPECT_EQ(counts.bindingSetBinds, 1u);
    EXPECT_EQ(counts.setsWritten, 0u);
}

// The control: without the listed layout the set's items are written into the per-draw set, as single binds are.
TEST(BindingSetCallsTest, AnUnlistedSetGoesIntoThePerDrawSet)
{
    const vulkan::DescriptorCounts counts = countFourDraws(false);
    EXPECT_EQ(counts.bindingSetBinds, 0u);
    EXPECT_EQ(counts.setsWritten, 1u);
}

} // namespace
} // namespace penumbra::testing
