// Binding sets on every configuration: a set gives the same picture as the single bind calls it replaces, survives a
// pipeline change, and feeds dispatches whose hazards the RHI still orders (HazardTest has the negative control);
// all of it also with pipelines that list the set's layout (on Vulkan the set's own descriptor set, bound with one
// call: tests/backends/BindingSetCallsTest.cpp), where single binds over part of a set still take their place.
#include "ComputeScenes.hpp"
#include "GpuTesting.hpp"
#include "TintedImageShaders.hpp"

#include "penumbra/rhi/Image.hpp"

#include <glm/vec4.hpp>

namespace penumbra::testing {
namespace {

// The tint alone: binding 1 is not declared, so a set that holds it leaves it unused.
const char* const tintOnlyFragmentGlsl = R"(#version 450
layout(location = 0) in vec4 color;
layout(location = 0) out vec4 result;
void main() { result = color; }
)";

class BindingSetTest : public GpuTest {
protected:
    void SetUp() override
    {
        GpuTest::SetUp();
        picture = device->createTexture({.width = 4,
                                         .height = 4,
                                         .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                         .debugName = "picture"});
        const rhi::Attachment attachment{picture.get(), 0};
        target = device->createFramebuffer({.colors = {&attachment, 1}, .debugName = "target"});
        image = device->createTexture({.width = 1, .height = 1, .debugName = "image"});
        const std::array<std::uint8_t, 4> texel{255, 128, 255, 255};
        device->writeTexture(*image, 0, 0, std::as_bytes(std::span(texel)));
        sampler = device->createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});
        tint = device->createBuffer({.size = 16, .usage = rhi::BufferUsage::Uniform, .debugName = "tint"});
        tint->writeObject(glm::vec4(0.0f, 1.0f, 1.0f, 1.0f));
        vertex = device->createShader({rhi::ShaderStage::Vertex, kTintedImageVertexGlsl, "set.vert"});
        fragment = device->createShader({rhi::ShaderStage::Fragment, kTintedImageFragmentGlsl, "set.frag"});
        tintOnly = device->createShader({rhi::ShaderStage::Fragment, tintOnlyFragmentGlsl, "tint.frag"});
        pipeline = device->createPipeline(
            {.vertex = vertex.get(), .fragment = fragment.get(), .colorTargets = {{}}, .debugName = "set"});
        tintPipeline = device->createPipeline(
            {.vertex = vertex.get(), .fragment = tintOnly.get(), .colorTargets = {{}}, .debugName = "tint"});
        layout = device->createBindingSetLayout(
            {.items = {{1, rhi::BindingKind::SampledTexture}, {0, rhi::BindingKind::UniformBuffer}},
             .debugName = "tint and image"});
        listed = device->createPipeline({.vertex = vertex.get(),
                                         .fragment = fragment.get(),
                                         .colorTargets = {{}},
                                         .bindingSetLayouts = {layout.get()},
                                         .debugName = "set, listed"});
        listedTint = device->createPipeline({.vertex = vertex.get(),
                                             .fragment = tintOnly.get(),
                                             .colorTargets = {{}},
                                             .bindingSetLayouts = {layout.get()},
                                             .debugName = "tint, listed"});
        set = device->createBindingSet({.layout = layout.get(),
                                        .items = {rhi::BindingSetItem::uniformBuffer(0, *tint, 0, 16),
                                                  rhi::BindingSetItem::sampledTexture(1, *image, *sampler)},
                                        .debugName = "tint and image"});
    }

    // Draws `drawn` over the target with what `bind` binds, and returns the picture's first pixel.
    Rgba draw(const rhi::Pipeline& drawn, const std::function<void(rhi::CommandList&)>& bind)
    {
        auto list = device->createCommandList();
        list->beginPass({.framebuffer = target.get()});
        bind(*list);
        list->bindPipeline(drawn);
        list->draw(3);
        list->endPass();
        device->submit(*list);
        return pixel(rhi::readTexture(*device, *picture), 0, 0);
    }

    std::unique_ptr<rhi::Texture> picture, image;
    std::unique_ptr<rhi::Framebuffer> target;
    std::unique_ptr<rhi::Sampler> sampler;
    std::unique_ptr<rhi::Buffer> tint;
    std::unique_ptr<rhi::Shader> vertex, fragment, tintOnly;
    std::unique_ptr<rhi::Pipeline> pipeline, tintPipeline;
    std::unique_ptr<rhi::Pipeline> listed, listedTint; // list the set's layout
    std::unique_ptr<rhi::BindingSetLayout> layout;
    std::unique_ptr<rhi::BindingSet> set;
};

TEST_F(BindingSetTest, ASetDrawsWhatItsSingleBindsDraw)
{
    const Rgba single = draw(*pipeline, [&](rhi::CommandList& list) {
        list.bindUniformBuffer(0, *tint, 0, 16);
        list.bindTexture(1, *image, *sampler);
    });
    const Rgba bySet = draw(*pipeline, [&](rhi::CommandList& list) { list.bindBindingSet(*set); });
    EXPECT_EQ(single, (Rgba{0, 128, 255, 255})) << describe(single);
    EXPECT_EQ(bySet, single) << describe(bySet);
}

TEST_F(BindingSetTest, ASetOutlivesAPipelineChangeAndServesPipelinesThatReadPartOfIt)
{
    const Rgba tinted = draw(*tintPipeline, [&](rhi::CommandList& list) {
        list.bindBindingSet(*set);
        list.bindPipeline(*pipeline);
        list.draw(3);
    });
    EXPECT_EQ(tinted, (Rgba{0, 255, 255, 255})) << describe(tinted);
}

TEST_F(BindingSetTest, APipelineListingTheLayoutDrawsTheSameThroughTheSetOrSingleBinds)
{
    const Rgba bySet = draw(*listed, [&](rhi::CommandList& list) { list.bindBindingSet(*set); });
    const Rgba single = draw(*listed, [&](rhi::CommandList& list) {
        list.bindUniformBuffer(0, *tint, 0, 16);
        list.bindTexture(1, *image, *sampler);
    });
    EXPECT_EQ(bySet, (Rgba{0, 128, 255, 255})) << describe(bySet);
    EXPECT_EQ(single, bySet) << describe(single);
    const Rgba tinted = draw(*listedTint, [&](rhi::CommandList& list) {
        list.bindBindingSet(*set);
        list.bindPipeline(*listed);
        list.draw(3);
    });
    EXPECT_EQ(tinted, (Rgba{0, 255, 255, 255})) << describe(tinted);
}

// A single bind after a set replaces the set's item at that binding, and the set's other items stay.
TEST_F(BindingSetTest, ASingleBindOverASetTakesThatBinding)
{
    auto red = device->createBuffer({.size = 16, .usage = rhi::BufferUsage::Uniform, .debugName = "red"});
    red->writeObject(glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    for (const rhi::Pipeline* drawn : {pipeline.get(), listed.get()}) {
        const Rgba replaced = draw(*drawn, [&](rhi::CommandList& list) {
            list.bindBindingSet(*set);
            list.bindUniformBuffer(0, *red, 0, 16);
        });
        EXPECT_EQ(replaced, (Rgba{255, 0, 0, 255})) << drawn->desc().debugName << ": " << describe(replaced);
    }
}

// A pipeline that lists the layout but reads only part of it, drawn with a single bind over the set or with single
// binds alone: Vulkan writes a set of the layout from what is bound, every binding of it (lavapipe read the image
// view of the binding left unwritten, which the shaders do not read, and crashed; the renderer's lit pipelines read
// part of the shadow maps' layout).
TEST_F(BindingSetTest, SingleBindsServeAPipelineThatReadsPartOfTheListedLayout)
{
    auto red = device->createBuffer({.size = 16, .usage = rhi::BufferUsage::Uniform, .debugName = "red"});
    red->writeObject(glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    const Rgba overSet = draw(*listedTint, [&](rhi::CommandList& list) {
        list.bindBindingSet(*set);
        list.bindUniformBuffer(0, *red, 0, 16);
    });
    EXPECT_EQ(overSet, (Rgba{255, 0, 0, 255})) << describe(overSet);
    const Rgba alone = draw(*listedTint, [&](rhi::CommandList& list) { list.bindUniformBuffer(0, *red, 0, 16); });
    EXPECT_EQ(alone, (Rgba{255, 0, 0, 255})) << describe(alone);
}

TEST_F(BindingSetTest, TheSetKeepsItsItemsSortedAndACopyOfItsLayout)
{
    layout.reset();
    ASSERT_EQ(set->items().size(), 2u);
    EXPECT_EQ(set->items()[0].binding, 0u);
    EXPECT_EQ(set->items()[1].kind, rhi::BindingKind::SampledTexture);
    EXPECT_EQ(set->layout().debugName, "tint and image");
    EXPECT_EQ(set->layout().items.front().binding, 0u);
}

TEST_F(BindingSetTest, DispatchesThroughASetAreOrdered)
{
    const ImageSum sum = storageImageSum(*device, {.bindingSet = true});
    EXPECT_EQ(sum.red, 16u * (15u * 16u / 2u)); // each row holds red 0..15
    const ImageSum listedSum = storageImageSum(*device, {.bindingSet = true, .listedLayout = true});
    EXPECT_EQ(listedSum.red, sum.red);
}

} // namespace
} // namespace penumbra::testing
