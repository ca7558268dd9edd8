// The RHI's threading contract for command lists (rhi::Device): lists of one device recorded on several threads at
// once, one list per thread, reading the same pipeline and buffers, then submitted on the device's thread, run in
// the order of submission and draw what a single thread draws.
#include "GpuTesting.hpp"
#include "TestPattern.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <thread>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kThreads = 4;
constexpr std::uint32_t kSize = 32;
using Link = std::array<std::uint32_t, 4>; // a link of the chain of buffer copies
constexpr Link kValue{0xC0FFEE, 1, 2, 3};

// What every thread draws with: made on the device's thread.
struct Shared {
    std::unique_ptr<rhi::Shader> vertex, fragment;
    std::unique_ptr<rhi::Pipeline> pipeline;
    std::unique_ptr<rhi::Buffer> uniforms, vertices;
    std::uint32_t vertexCount = 0;
};

// One thread's target and list.
struct PerThread {
    std::unique_ptr<rhi::Texture> color, depth;
    std::unique_ptr<rhi::Framebuffer> framebuffer;
    std::unique_ptr<rhi::CommandList> commands;
};

Shared makeShared(rhi::Device& device)
{
    Shared s;
    s.vertex = device.createShader(pattern::patternVertexShader());
    s.fragment = device.createShader(shaders::load("pattern.frag"));
    s.pipeline = device.createPipeline({
        .vertex = s.vertex.get(),
        .fragment = s.fragment.get(),
        .vertexLayout = {.buffers = {{.stride = sizeof(pattern::PatternVertex)}},
                         .attributes = {{.location = 0, .format = rhi::VertexFormat::Float3, .offset = 0},
                                        {.location = 1,
                                         .format = rhi::VertexFormat::Float4,
                                         .offset = offsetof(pattern::PatternVertex, color)}}},
        .depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer},
        .colorTargets = {{.format = rhi::Format::RGBA8}},
        .depthFormat = rhi::Format::D32F,
        .debugName = "pattern",
    });
    const glm::mat4 projection = device.conventions().perspective(1.5707964f, 1.0f, 0.1f, 100.0f);
    s.uniforms = device.createBuffer({.size = sizeof(glm::mat4), .usage = rhi::BufferUsage::Uniform});
    s.uniforms->writeObject(projection);
    const std::vector<pattern::PatternVertex> triangles = pattern::testPattern();
    s.vertexCount = std::uint32_t(triangles.size());
    s.vertices = device.createBuffer({.size = std::span(triangles).size_bytes(), .usage = rhi::BufferUsage::Vertex});
    s.vertices->write(0, std::as_bytes(std::span(triangles)));
    return s;
}

PerThread makePerThread(rhi::Device& device)
{
    PerThread t;
    t.color = device.createTexture(
        {.width = kSize, .height = kSize, .format = rhi::Format::RGBA8, .usage = rhi::TextureUsage::RenderTarget});
    t.depth = device.createTexture(
        {.width = kSize, .height = kSize, .format = rhi::Format::D32F, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment color{t.color.get(), 0};
    t.framebuffer = device.createFramebuffer({.colors = {&color, 1}, .depth = {t.depth.get(), 0}});
    t.commands = device.createCommandList();
    return t;
}

// Thread i's recording: the pattern into its own target, cleared to a grey of its own, and the copy of chain link
// i into link i + 1.
void record(const Shared& s, PerThread& t, std::uint32_t i, const rhi::Buffer& from, rhi::Buffer& to)
{
    rhi::CommandList& commands = *t.commands;
    commands.pushLabel(fmt::format("thread {}", i));
    const float grey = float(i + 1) / float(kThreads + 1);
    commands.beginPass({.framebuffer = t.framebuffer.get(), .clearColor = glm::vec4(grey, grey, grey, 1)});
    commands.bindPipeline(*s.pipeline);
    commands.bindUniformBuffer(0, *s.uniforms, 0, sizeof(glm::mat4));
    commands.bindVertexBuffer(0, *s.vertices);
    commands.draw(s.vertexCount);
    commands.endPass();
    commands.copyBuffer(from, 0, to, 0, from.desc().size);
    commands.popLabel();
}

TEST(RecordingOnThreads, ListsRecordedOnSeveralThreadsRunInSubmissionOrderAndDrawAsOneThreadDoes)
{
    std::vector<SkippedConfiguration> skipped;
    for (const std::string& configuration : {std::string("vulkan"), std::string("opengl")}) {
        std::unique_ptr<rhi::Device> device;
        try {
            device = createValidatedDevice(configuration);
        } catch (const rhi::UnsupportedError& e) {
            skipped.push_back({configuration, e.what()});
            continue;
        }
        const Shared shared = makeShared(*device);
        std::vector<PerThread> lists;
        // The chain: link 0 holds a value, list i copies link i into link i + 1, so the value reaches the last link
        // only when the lists run in the order 0, 1, ...
        std::vector<std::unique_ptr<rhi::Buffer>> chain;
        for (std::uint32_t i = 0; i <= kThreads; ++i) {
            chain.push_back(device->createBuffer({.size = sizeof(Link), .usage = rhi::BufferUsage::Readback}));
            chain.back()->writeObject(Link{});
        }
        chain[0]->writeObject(kValue);
        for (std::uint32_t i = 0; i < kThreads; ++i)
            lists.push_back(makePerThread(*device));

        // One thread records alone first: the reference picture of list 0.
        {
            std::jthread alone([&] { record(shared, lists[0], 0, *chain[0], *chain[1]); });
        }
        device->submit(*lists[0].commands);
        const rhi::Image reference = rhi::readTexture(*device, *lists[0].color);
        chain[1]->writeObject(Link{});

        {
            std::vector<std::jthread> threads;
            for (std::uint32_t i = 0; i < kThreads; ++i)
                threads.emplace_back([&, i] { record(shared, lists[i], i, *chain[i], *chain[i + 1]); });
        }
        for (PerThread& t : lists)
            device->submit(*t.commands);

        Link last{};
        chain.back()->read(0, std::as_writable_bytes(std::span(last)));
        EXPECT_EQ(last, kValue) << configuration;
        for (std::uint32_t i = 0; i < kThreads; ++i) {
            const rhi::Image picture = rhi::readTexture(*device, *lists[i].color);
            if (i == 0) {
                EXPECT_EQ(picture.bytes, reference.bytes) << configuration << ": list 0 recorded beside others";
            }
            // The top-left marker is drawn over every clear; the top-middle pixel shows the thread's own grey.
            EXPECT_EQ(pixel(picture, 1, 1), (Rgba{255, 0, 0, 255})) << configuration << " thread " << i;
            const std::uint8_t grey = pixel(picture, kSize / 2, 0)[0];
            EXPECT_NEAR(grey, 255.0 * (i + 1) / (kThreads + 1), 1.0) << configuration << " thread " << i;
        }
        expectNoDebugMessages(*device);
    }
    reportSkipped(skipped);
}

} // namespace
} // namespace penumbra::testing
