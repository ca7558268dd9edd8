// The frame as a graph of passes: which built-in passes run for a frame, that the debug views are culled unless
// asked for, an application's pass placed after the lit pass reading the lit image, and the errors of a pass that
// names a texture or a pass the frame does not have, or touches a texture it did not declare.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"

#include "graph/FrameGraph.hpp"
#include "graph/PassBarriers.hpp"
#include "graph/TransientSlots.hpp"

#include <array>
#include <fmt/format.h>
#include <functional>
#include <gtest/gtest.h>
#include <map>

namespace penumbra::testing {
namespace {

namespace frame = render::frame;

constexpr std::uint32_t kGraphWidth = 160;
constexpr std::uint32_t kGraphHeight = 90;

std::vector<std::string> passNames(const render::FrameStats& stats)
{
    std::vector<std::string> names;
    for (const render::PassTiming& pass : stats.passes)
        names.push_back(pass.name);
    return names;
}

// An application's pass: the lit image at half brightness into a texture of its own.
class HalfBrightPass final : public render::FramePass {
public:
    HalfBrightPass(rhi::Device& device, std::string output, std::string read = std::string(frame::kLitImage))
        : output_(std::move(output)), read_(std::move(read))
    {
        vertex_ = device.createShader({rhi::ShaderStage::Vertex, R"(#version 450
            const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
            void main() { gl_Position = vec4(corners[gl_VertexIndex], 0.0, 1.0); })"});
        fragment_ = device.createShader({rhi::ShaderStage::Fragment, R"(#version 450
            layout(binding = 0) uniform sampler2D lit;
            layout(location = 0) out vec4 result;
            void main() { result = vec4(texelFetch(lit, ivec2(gl_FragCoord.xy), 0).rgb * 0.5, 1.0); })"});
        pipeline_ = device.createPipeline({.vertex = vertex_.get(),
                                           .fragment = fragment_.get(),
                                           .colorTargets = {{.format = render::kLitColorFormat}}});
        sampler_ = device.createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});
    }

    std::string name() const override { return "half bright"; }
    bool setup(render::FramePassBuilder& builder) override
    {
        builder.read(read_);
        builder.write(output_);
        return true;
    }
    void execute(const render::FramePassContext& context) override
    {
        draw(context.commands(), context.framebuffer({output_}), context.texture(frame::kLitImage));
    }
    // Half of `image` into `target`, in a pass of its own.
    void draw(rhi::CommandList& commands, const rhi::Framebuffer& target, const rhi::Texture& image) const
    {
        commands.beginPass({.framebuffer = &target});
        commands.bindPipeline(*pipeline_);
        commands.bindTexture(0, image, *sampler_);
        commands.draw(3);
        commands.endPass();
    }

private:
    std::string output_, read_;
    std::unique_ptr<rhi::Shader> vertex_, fragment_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
    std::unique_ptr<rhi::Sampler> sampler_;
};

std::unique_ptr<rhi::Texture> colorTexture(rhi::Device& device)
{
    return device.createTexture({.width = kGraphWidth,
                                 .height = kGraphHeight,
                                 .format = render::kLitColorFormat,
                                 .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget});
}

class FrameGraphTest : public GpuTest {
protected:
    void SetUp() override
    {
        GpuTest::SetUp();
        if (device)
            commands = device->createCommandList();
    }
    void TearDown() override
    {
        commands.reset();
        GpuTest::TearDown();
    }

    std::unique_ptr<rhi::CommandList> commands;
};

TEST_F(FrameGraphTest, ForwardFrameRunsTheAtlasesThePrepassAndTheLitPass)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    const render::FrameStats stats = renderer.render(scene.camera, litFrame(kGraphWidth, kGraphHeight, true, 1));
    EXPECT_EQ(passNames(stats), (std::vector<std::string>{"directional atlas", "local atlas", "depth prepass", "lit"}));
    // The debug views are in the graph, culled: nothing reads what they write.
    const std::string dot = renderer.frameGraphDot();
    EXPECT_NE(dot.find("cascade view\\n(culled"), std::string::npos) << dot;
    EXPECT_NE(dot.find("msaa resolve\\n(off this frame)"), std::string::npos) << dot;
}

TEST_F(FrameGraphTest, MultisampledScreenSpaceFrameResolvesAndCollects)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    render::FrameDesc desc = litFrame(kGraphWidth, kGraphHeight, true, 4);
    desc.shadowPath = render::ShadowPath::ScreenSpace;
    desc.cascadeView = true;
    const render::FrameStats stats = renderer.render(scene.camera, desc);
    EXPECT_EQ(passNames(stats),
              (std::vector<std::string>{"directional atlas", "local atlas", "depth prepass", "receiver prepass",
                                        "screen-space shadows", "lit", "msaa resolve", "cascade view"}));
    if (device->capabilities().timestamps) {
        for (const render::PassTiming& pass : stats.passes)
            EXPECT_TRUE(pass.gpuMs.has_value()) << pass.name;
    }
}

TEST_F(FrameGraphTest, ApplicationPassAfterTheLitPassReadsTheLitImage)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    const std::unique_ptr<rhi::Texture> output = colorTexture(*device);
    renderer.addTexture("half bright image", *output);
    renderer.addPass(std::make_shared<HalfBrightPass>(*device, "half bright image"),
                     render::PassPlacement::after(std::string(frame::kLitPass)));
    const render::FrameStats stats = renderer.render(scene.camera, litFrame(kGraphWidth, kGraphHeight, true, 1));
    ASSERT_EQ(passNames(stats).back(), "half bright");
    const rhi::Image lit = rhi::readTexture(*device, renderer.litImage());
    const rhi::Image half = rhi::readTexture(*device, *output);
    ASSERT_EQ(lit.bytes.size(), half.bytes.size());
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < lit.bytes.size(); ++i) {
        const int expected = i % 4 == 3 ? 255 : int(lit.bytes[i]) / 2;
        wrong += std::abs(int(half.bytes[i]) - expected) > 1 ? 1 : 0;
    }
    EXPECT_EQ(wrong, 0u);
}

// An application's compute pass: counts the lit image's pixels whose red is above 0 into a buffer of its own, whose
// block is generated from its C++ declaration.
struct LitPixelCount {
    std::uint32_t litPixels = 0;
};
constexpr std::array kLitPixelCountFields{PENUMBRA_SHADER_FIELD(LitPixelCount, litPixels)};
constexpr shaders::ShaderStruct kLitPixelCountBlock{"LitPixelCount", sizeof(LitPixelCount), kLitPixelCountFields};
static_assert(shaders::matchesLayout(kLitPixelCountBlock, shaders::BlockLayout::Std430));

class LitPixelCountPass final : public render::FramePass {
public:
    LitPixelCountPass(rhi::Device& device, std::string output) : output_(std::move(output))
    {
        const std::unique_ptr<rhi::Shader> shader = device.createShader(
            {rhi::ShaderStage::Compute,
             R"(#version 450
            layout(local_size_x = 8, local_size_y = 8) in;
            layout(binding = 0) uniform sampler2D lit;
            #include "lit_pixel_count_block.glsl"
            void main()
            {
                const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
                if (all(lessThan(p, textureSize(lit, 0))) && texelFetch(lit, p, 0).r > 0.0)
                    atomicAdd(count.litPixels, 1u);
            })",
             "lit_pixel_count.comp",
             {{"lit_pixel_count_block.glsl",
               shaders::storageBlockGlsl(kLitPixelCountBlock, 1, "count", shaders::BlockAccess::ReadWrite)}}});
        pipeline_ = device.createComputePipeline(
            {.compute = shader.get(), .storageLayouts = {shaders::storageLayout(kLitPixelCountBlock)}});
        sampler_ = device.createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});
    }

    std::string name() const override { return "lit pixel count"; }
    bool setup(render::FramePassBuilder& builder) override
    {
        builder.read(frame::kLitImage);
        builder.write(output_, render::ResourceUse::StorageWrite);
        return true;
    }
    void execute(const render::FramePassContext& context) override
    {
        rhi::CommandList& commands = context.commands();
        commands.bindComputePipeline(*pipeline_);
        commands.bindTexture(0, context.texture(frame::kLitImage), *sampler_);
        commands.bindStorageBuffer(1, context.buffer(output_), 0, sizeof(LitPixelCount));
        commands.dispatch((kGraphWidth + 7) / 8, (kGraphHeight + 7) / 8);
    }

private:
    std::string output_;
    std::unique_ptr<rhi::ComputePipeline> pipeline_;
    std::unique_ptr<rhi::Sampler> sampler_;
};

TEST_F(FrameGraphTest, ApplicationPassWritesABufferOfItsOwn)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    const std::unique_ptr<rhi::Buffer> count = device->createBuffer(
        {.size = sizeof(LitPixelCount), .usage = rhi::BufferUsage::Storage, .debugName = "lit pixel count"});
    count->writeObject(LitPixelCount{});
    renderer.addBuffer("lit pixel count", *count);
    renderer.addPass(std::make_shared<LitPixelCountPass>(*device, "lit pixel count"),
                     render::PassPlacement::after(std::string(frame::kLitPass)));
    const render::FrameStats stats = renderer.render(scene.camera, litFrame(kGraphWidth, kGraphHeight, true, 1));
    ASSERT_EQ(passNames(stats).back(), "lit pixel count");
    const rhi::Image lit = rhi::readTexture(*device, renderer.litImage());
    std::uint32_t expected = 0;
    for (std::size_t i = 0; i < lit.bytes.size(); i += 4)
        expected += lit.bytes[i] != std::byte{0} ? 1 : 0;
    LitPixelCount counted;
    count->read(0, std::as_writable_bytes(std::span(&counted, 1)));
    EXPECT_GT(expected, 0u);
    EXPECT_EQ(counted.litPixels, expected);
}

// Without addBuffer the frame has no buffer of that name.
TEST_F(FrameGraphTest, ApplicationBufferNotAddedIsRefused)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    renderer.addPass(std::make_shared<LitPixelCountPass>(*device, "lit pixel count"),
                     render::PassPlacement::after(std::string(frame::kLitPass)));
    const std::string error =
        errorOf([&] { renderer.render(scene.camera, litFrame(kGraphWidth, kGraphHeight, true, 1)); });
    EXPECT_NE(error.find("pass 'lit pixel count' uses resource 'lit pixel count', which the frame does not have"),
              std::string::npos)
        << error;
}

// A pass whose writes lead to no output is culled: the cascade view's image is no output of a frame without the view.
TEST_F(FrameGraphTest, ApplicationPassWhoseWritesNobodyReadsIsCulled)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    renderer.addPass(std::make_shared<HalfBrightPass>(*device, std::string(frame::kCascadeView)),
                     render::PassPlacement::before(std::string(frame::kCascadeViewPass)));
    const render::FrameStats stats = renderer.render(scene.camera, litFrame(kGraphWidth, kGraphHeight, true, 1));
    const std::vector<std::string> names = passNames(stats);
    EXPECT_EQ(std::find(names.begin(), names.end(), "half bright"), names.end());
    EXPECT_NE(renderer.frameGraphDot().find("half bright\\n(culled"), std::string::npos);
}

TEST_F(FrameGraphTest, PlacementNamingNoPassIsRefused)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    const std::string error = errorOf([&] {
        renderer.addPass(std::make_shared<HalfBrightPass>(*device, "out"), render::PassPlacement::after("fog"));
    });
    EXPECT_NE(error.find("placed after 'fog', which is not a pass of the frame ('skinning', 'static maps'"),
              std::string::npos)
        << error;
}

TEST_F(FrameGraphTest, UnknownTextureIsRefusedNamingThePass)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    renderer.addPass(std::make_shared<HalfBrightPass>(*device, "nowhere"),
                     render::PassPlacement::after(std::string(frame::kLitPass)));
    const std::string error =
        errorOf([&] { renderer.render(scene.camera, litFrame(kGraphWidth, kGraphHeight, true, 1)); });
    EXPECT_NE(error.find("pass 'half bright' uses texture 'nowhere', which the frame does not have"), std::string::npos)
        << error;
}

// The pass declares the lit depth but binds the lit image.
TEST_F(FrameGraphTest, UndeclaredTextureIsRefused)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    const std::unique_ptr<rhi::Texture> output = colorTexture(*device);
    renderer.addTexture("half bright image", *output);
    renderer.addPass(std::make_shared<HalfBrightPass>(*device, "half bright image", std::string(frame::kLitDepth)),
                     render::PassPlacement::after(std::string(frame::kLitPass)));
    const std::string error =
        errorOf([&] { renderer.render(scene.camera, litFrame(kGraphWidth, kGraphHeight, true, 1)); });
    EXPECT_NE(error.find("pass 'half bright' did not declare texture 'lit image'"), std::string::npos) << error;
}

// A pass of setup and execute functions, for the graph's own tests.
class FunctionPass final : public render::FramePass {
public:
    FunctionPass(std::string name, std::function<void(render::FramePassBuilder&)> setup,
                 std::function<void(const render::FramePassContext&)> execute = {})
        : name_(std::move(name)), setup_(std::move(setup)), execute_(std::move(execute))
    {
    }
    std::string name() const override { return name_; }
    bool setup(render::FramePassBuilder& builder) override
    {
        setup_(builder);
        return true;
    }
    void execute(const render::FramePassContext& context) override
    {
        if (execute_)
            execute_(context);
    }

private:
    std::string name_;
    std::function<void(render::FramePassBuilder&)> setup_;
    std::function<void(const render::FramePassContext&)> execute_;
};

// Sampled too: the passes read them as sampled textures, which the RHI's barriers check against the usage.
const rhi::TextureDesc kTransient{.width = 8,
                                  .height = 8,
                                  .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled};

// Two textures of one description used one after the other are one texture; one used alongside is another.
TEST_F(FrameGraphTest, TransientTexturesShareWhereTheirPassesDoNotOverlap)
{
    render::FrameGraph graph(*device);
    const std::unique_ptr<rhi::Texture> output = colorTexture(*device);
    std::map<std::string, const rhi::Texture*> seen;
    const auto remember = [&](const char* name) {
        return [&seen, name](const render::FramePassContext& c) { seen[name] = &c.texture(name); };
    };
    FunctionPass first(
        "first", [](render::FramePassBuilder& b) { b.write("a"); }, remember("a"));
    FunctionPass second(
        "second",
        [](render::FramePassBuilder& b) {
            b.read("a");
            b.write("b");
        },
        remember("b"));
    FunctionPass third(
        "third",
        [](render::FramePassBuilder& b) {
            b.read("b");
            b.write("c");
        },
        remember("c"));
    FunctionPass last("last", [](render::FramePassBuilder& b) {
        b.read("c");
        b.write("out");
    });
    graph.importTexture("out", *output, true);
    for (const char* name : {"a", "b", "c"})
        graph.createTexture(name, kTransient);
    for (render::FramePass* pass : std::initializer_list<render::FramePass*>{&first, &second, &third, &last})
        graph.addPass(*pass);
    graph.compile();
    graph.execute(*commands);
    device->submit(*commands);
    EXPECT_EQ(seen["a"], seen["c"]); // a's last use (second) is before c's first (third)
    EXPECT_NE(seen["a"], seen["b"]);
    EXPECT_NE(seen["b"], seen["c"]);
}

TEST_F(FrameGraphTest, ReadBeforeAnyWriteIsRefused)
{
    render::FrameGraph graph(*device);
    const std::unique_ptr<rhi::Texture> output = colorTexture(*device);
    FunctionPass early("early", [](render::FramePassBuilder& b) {
        b.read("made");
        b.write("out");
    });
    FunctionPass late("late", [](render::FramePassBuilder& b) { b.write("made"); });
    graph.importTexture("out", *output, true);
    graph.createTexture("made", kTransient);
    graph.addPass(early);
    graph.addPass(late);
    EXPECT_EQ(errorOf([&] { graph.compile(); }), "frame graph: pass 'early' reads 'made' before any pass writes it");
}

// The graph derives each pass's barriers from its declared uses and hands them to the RHI, which then holds the pass
// to them: a pass that samples a texture of the frame it did not declare (held from an earlier pass, so the graph's
// own check by name cannot see it) is reported at its draw, naming the pass and the texture; declared, it draws.
TEST_F(FrameGraphTest, UndeclaredReadCatchesFault)
{
    const std::unique_ptr<rhi::Texture> output = colorTexture(*device);
    const std::unique_ptr<rhi::Texture> made =
        device->createTexture({.width = 8,
                               .height = 8,
                               .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                               .debugName = "made"});
    const HalfBrightPass sampling(*device, "out");
    for (const bool declared : {true, false}) {
        SCOPED_TRACE(declared ? "declared" : "not declared");
        render::FrameGraph graph(*device);
        FunctionPass writer(
            "writer",
            [](render::FramePassBuilder& b) {
                b.write("made");
                b.keep();
            },
            [](const render::FramePassContext& c) {
                c.commands().beginPass({.framebuffer = &c.framebuffer({"made"})});
                c.commands().endPass();
            });
        FunctionPass reader(
            "reader",
            [declared](render::FramePassBuilder& b) {
                if (declared)
                    b.read("made");
                b.write("out");
            },
            [&](const render::FramePassContext& c) { sampling.draw(c.commands(), c.framebuffer({"out"}), *made); });
        graph.importTexture("out", *output, true);
        graph.importTexture("made", *made);
        graph.addPass(writer);
        graph.addPass(reader);
        graph.compile();
        if (declared) {
            graph.execute(*commands);
            EXPECT_NO_THROW(device->submit(*commands));
            continue;
        }
        EXPECT_EQ(errorOf([&] { graph.execute(*commands); }),
                  "draw: pass 'reader' uses texture 'made' as ShaderRead (binding 0, 'lit'), but its "
                  "resourceBarriers do not declare it");
    }
}

// A buffer that one pass writes and another reads is a frame resource as a texture is: the graph orders the two by the
// declared uses (a copy into it, a copy out of it), and the RHI holds the reader to its declaration: reading the buffer
// undeclared is reported at its copy, naming the pass and the buffer; declared, the bytes arrive.
TEST_F(FrameGraphTest, UndeclaredBufferReadCatchesFault)
{
    const std::array<std::uint32_t, 4> values{1, 2, 3, 4};
    const std::unique_ptr<rhi::Buffer> source = device->createBuffer({.size = sizeof values, .debugName = "source"});
    source->write(0, std::as_bytes(std::span(values)));
    const std::unique_ptr<rhi::Buffer> made = device->createBuffer({.size = sizeof values, .debugName = "made"});
    const std::unique_ptr<rhi::Buffer> out =
        device->createBuffer({.size = sizeof values, .usage = rhi::BufferUsage::Readback, .debugName = "out"});
    for (const bool declared : {true, false}) {
        SCOPED_TRACE(declared ? "declared" : "not declared");
        render::FrameGraph graph(*device);
        FunctionPass writer(
            "writer",
            [](render::FramePassBuilder& b) {
                b.write("made", render::ResourceUse::TransferDestination);
                b.keep();
            },
            [&](const render::FramePassContext& c) { c.commands().copyBuffer(*source, 0, *made, 0, sizeof values); });
        FunctionPass reader(
            "reader",
            [declared](render::FramePassBuilder& b) {
                if (declared)
                    b.read("made", render::ResourceUse::TransferSource);
                b.write("out", render::ResourceUse::TransferDestination);
            },
            [&](const render::FramePassContext& c) { c.commands().copyBuffer(*made, 0, *out, 0, sizeof values); });
        graph.importBuffer("out", *out, true);
        graph.importBuffer("made", *made);
        graph.addPass(writer);
        graph.addPass(reader);
        graph.compile();
        if (declared) {
            graph.execute(*commands);
            device->submit(*commands);
            std::array<std::uint32_t, 4> read{};
            out->read(0, std::as_writable_bytes(std::span(read)));
            EXPECT_EQ(read, values);
            continue;
        }
        EXPECT_EQ(errorOf([&] { graph.execute(*commands); }),
                  "copyBuffer: pass 'reader' uses buffer 'made' as CopySource (source), but its "
                  "resourceBarriers do not declare it");
    }
}

// A pass whose buffer nobody reads is culled as one whose texture nobody reads; the dot text draws buffers as
// cylinders with their uses named; a buffer use on a texture, and a texture use on a buffer, are refused.
TEST_F(FrameGraphTest, BufferWriterIsCulledUnlessItsBufferIsRead)
{
    const std::unique_ptr<rhi::Buffer> made = device->createBuffer(
        {.size = 16, .usage = rhi::BufferUsage::Storage | rhi::BufferUsage::Indirect, .debugName = "made"});
    const std::unique_ptr<rhi::Texture> output = colorTexture(*device);
    for (const bool read : {true, false}) {
        render::FrameGraph graph(*device);
        FunctionPass writer("writer",
                            [](render::FramePassBuilder& b) { b.write("made", render::ResourceUse::StorageWrite); });
        FunctionPass reader("reader", [read](render::FramePassBuilder& b) {
            if (read)
                b.read("made", render::ResourceUse::IndirectRead);
            b.write("out");
        });
        graph.importBuffer("made", *made);
        graph.importTexture("out", *output, true);
        graph.addPass(writer);
        graph.addPass(reader);
        graph.compile();
        const std::string dot = graph.dot();
        EXPECT_NE(dot.find("[shape=cylinder, label=\"made\"]"), std::string::npos) << dot;
        EXPECT_EQ(dot.find("writer\\n(culled") != std::string::npos, !read) << dot;
        EXPECT_EQ(dot.find("label=\"indirect read\"") != std::string::npos, read) << dot;
    }
    render::FrameGraph graph(*device);
    FunctionPass vertices("vertices",
                          [](render::FramePassBuilder& b) { b.read("out", render::ResourceUse::VertexRead); });
    graph.importTexture("out", *output, true);
    graph.addPass(vertices);
    EXPECT_THROW(
        {
            try {
                graph.compile();
            } catch (const rhi::Error& e) {
                EXPECT_STREQ(e.what(),
                             "frame graph: pass 'vertices' uses texture 'out' as vertex read, a use of buffers only");
                throw;
            }
        },
        rhi::Error);
}

// The frame's own buffers are resources of its graph: the caster culling pass writes the instance lists and indirect
// draws that the atlas passes read, the view culling pass those that the prepass and the lit pass read, the depth
// reduction writes the histogram the renderer reads after the frame.
TEST_F(FrameGraphTest, CulledCastersAndTheDepthHistogramAreFrameBuffers)
{
    const scene::Scene scene = scenes::makeShadowTestScene();
    render::SceneRenderer renderer(*device, scene);
    render::FrameDesc desc = litFrame(kGraphWidth, kGraphHeight, true, 1);
    desc.shadows.culling = shadows::CasterCullingMode::Gpu;
    desc.shadows.directional.projection = shadows::CascadeProjection::DepthFit;
    const render::FrameStats stats = renderer.render(scene.camera, desc);
    EXPECT_EQ(passNames(stats), (std::vector<std::string>{"caster culling", "view culling", "directional atlas",
                                                          "local atlas", "depth prepass", "lit", "depth reduction"}));
    const std::string dot = renderer.frameGraphDot();
    for (const std::string_view buffer :
         {frame::kCulledInstances, frame::kCulledDraws, frame::kViewCulledInstances, frame::kViewCulledDraws})
        EXPECT_NE(dot.find(fmt::format("[shape=cylinder, label=\"{}\"]", buffer)), std::string::npos) << dot;
    EXPECT_NE(dot.find("[shape=cylinder, label=\"depth histogram\", peripheries=2]"), std::string::npos) << dot;
    EXPECT_NE(dot.find("label=\"indirect read\""), std::string::npos) << dot;
}

// Objects that stand for a frame's textures and buffers in PassBarriers' tests.
struct BarrierObjects {
    int a = 0, b = 0, c = 0;
};
using rhi::ResourceState;

// A compute pass writes two buffers that two later passes read: the first reader's barrier makes both visible (one
// glMemoryBarrier, where llvmpipe finishes every one); the second reader declares its buffer again, unchanged.
TEST(PassBarriers, ReadsOfShaderWritesJoinTheFirstWait)
{
    const BarrierObjects o;
    const std::vector<std::vector<render::StateChange>> barriers = render::passBarriers({
        {{&o.a, ResourceState::ShaderWrite}, {&o.b, ResourceState::ShaderWrite}},
        {{&o.a, ResourceState::IndirectArgument}, {&o.a, ResourceState::VertexBuffer}},
        {{&o.c, ResourceState::RenderTarget}},
        {{&o.b, ResourceState::VertexBuffer}},
    });
    using Changes = std::vector<render::StateChange>;
    ASSERT_EQ(barriers.size(), 4u);
    EXPECT_EQ(barriers[1], (Changes{{&o.a, ResourceState::ShaderWrite,
                                     ResourceState::IndirectArgument | ResourceState::VertexBuffer},
                                    {&o.b, ResourceState::ShaderWrite, ResourceState::VertexBuffer}}));
    EXPECT_EQ(barriers[2], (Changes{{&o.c, ResourceState::Undefined, ResourceState::RenderTarget}}));
    EXPECT_EQ(barriers[3], (Changes{{&o.b, ResourceState::VertexBuffer, ResourceState::VertexBuffer}}));
}

// A barrier moves no further forward than its object's next use: a buffer written again in between is read after the
// second write's own barrier.
TEST(PassBarriers, AnObjectUsedInBetweenWaitsForItsNextUse)
{
    const BarrierObjects o;
    const std::vector<std::vector<render::StateChange>> barriers = render::passBarriers({
        {{&o.a, ResourceState::ShaderWrite}, {&o.b, ResourceState::ShaderWrite}},
        {{&o.a, ResourceState::ShaderRead}},
        {{&o.b, ResourceState::ShaderWrite}},
        {{&o.b, ResourceState::VertexBuffer}},
    });
    using Changes = std::vector<render::StateChange>;
    EXPECT_EQ(barriers[1], (Changes{{&o.a, ResourceState::ShaderWrite, ResourceState::ShaderRead},
                                    {&o.b, ResourceState::ShaderWrite, ResourceState::ShaderWrite}}));
    EXPECT_EQ(barriers[2], (Changes{{&o.b, ResourceState::ShaderWrite, ResourceState::ShaderWrite}}));
    EXPECT_EQ(barriers[3], (Changes{{&o.b, ResourceState::ShaderWrite, ResourceState::VertexBuffer}}));
}

// A pass that waits on no shader write takes no later pass's barrier: each reader waits where it reads.
TEST(PassBarriers, PassWithoutAWaitTakesNone)
{
    const BarrierObjects o;
    const std::vector<std::vector<render::StateChange>> barriers = render::passBarriers({
        {{&o.a, ResourceState::ShaderWrite}},
        {{&o.c, ResourceState::RenderTarget}},
        {{&o.a, ResourceState::VertexBuffer}},
    });
    using Changes = std::vector<render::StateChange>;
    EXPECT_EQ(barriers[1], (Changes{{&o.c, ResourceState::Undefined, ResourceState::RenderTarget}}));
    EXPECT_EQ(barriers[2], (Changes{{&o.a, ResourceState::ShaderWrite, ResourceState::VertexBuffer}}));
}

// Transient textures of one kind share a slot where their passes do not overlap, and keep their slots from frame to
// frame.
TEST(TransientSlots, TexturesShareWhereLifetimesDoNotOverlap)
{
    const std::vector<render::TransientLifetime> lifetimes{
        {.kind = 0, .firstPass = 0, .lastPass = 1}, // slot 0
        {.kind = 0, .firstPass = 1, .lastPass = 3}, // overlaps the first at pass 1: slot 1
        {.kind = 0, .firstPass = 2, .lastPass = 2}, // after the first: slot 0 again
        {.kind = 1, .firstPass = 0, .lastPass = 0}, // another kind: its own slot 0
        {.kind = 0, .firstPass = 4, .lastPass = 5}, // after all: slot 0
    };
    EXPECT_EQ(render::assignTransientSlots(lifetimes), (std::vector<std::uint32_t>{0, 1, 0, 0, 0}));
}

} // namespace
} // namespace penumbra::testing
