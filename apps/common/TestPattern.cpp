#include "TestPattern.hpp"

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <glm/gtc/constants.hpp>

namespace penumbra::pattern {
namespace {

constexpr std::uint32_t kPatternBinding = 0;
constexpr std::array kPatternFields{PENUMBRA_SHADER_FIELD(PatternUniforms, projection)};
constexpr shaders::ShaderStruct kPatternBlock{"Pattern", sizeof(PatternUniforms), kPatternFields};
static_assert(shaders::matchesLayout(kPatternBlock, shaders::BlockLayout::Std140));

} // namespace

rhi::ShaderSource patternVertexShader()
{
    rhi::ShaderSource source = shaders::load("pattern.vert");
    source.includes.push_back(
        {"pattern_blocks.glsl", shaders::uniformBlockGlsl(kPatternBlock, kPatternBinding, "pattern")});
    return source;
}

std::vector<PatternVertex> testPattern()
{
    const glm::vec4 red(1, 0, 0, 1), green(0, 1, 0, 1), blue(0, 0, 1, 1), yellow(1, 1, 0, 1), cyan(0, 1, 1, 1),
        magenta(1, 0, 1, 1);
    // Every triangle is counter-clockwise in NDC (y up).
    return {
        // Markers: top-left red, top-right green, bottom-left blue.
        {{-0.95f, 0.95f, 5.0f}, red},
        {{-0.95f, 0.55f, 5.0f}, red},
        {{-0.55f, 0.95f, 5.0f}, red},
        {{0.95f, 0.95f, 5.0f}, green},
        {{0.55f, 0.95f, 5.0f}, green},
        {{0.95f, 0.55f, 5.0f}, green},
        {{-0.95f, -0.95f, 5.0f}, blue},
        {{-0.55f, -0.95f, 5.0f}, blue},
        {{-0.95f, -0.55f, 5.0f}, blue},
        // Two large triangles crossing each other in depth: yellow leans away to the right,
        // cyan away to the left, so the visible edge between them is the line where depths meet.
        {{-0.6f, -0.5f, 2.0f}, yellow},
        {{0.6f, -0.5f, 8.0f}, yellow},
        {{0.0f, 0.6f, 5.0f}, yellow},
        {{-0.6f, -0.3f, 8.0f}, cyan},
        {{0.6f, -0.3f, 2.0f}, cyan},
        {{0.0f, 0.8f, 5.0f}, cyan},
        // A magenta sliver behind everything.
        {{-0.9f, -0.1f, 9.0f}, magenta},
        {{0.9f, -0.1f, 9.0f}, magenta},
        {{0.9f, 0.1f, 9.0f}, magenta},
    };
}

PatternRenderer::PatternRenderer(rhi::Device& device, const PatternTarget& target)
    : device_(device), target_(target),
      projection_(device.conventions().perspective(glm::half_pi<float>(), 1.0f, target.zNear, target.zFar)),
      vertexShader_(device.createShader(patternVertexShader())),
      fragmentShader_(device.createShader(shaders::load("pattern.frag"))),
      color_(
          device.createTexture({.width = target.width,
                                .height = target.height,
                                .format = rhi::Format::RGBA8,
                                .usage = target.sampled ? rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled
                                                        : rhi::TextureUsage::RenderTarget,
                                .debugName = "pattern.color"})),
      depth_(device.createTexture({.width = target.width,
                                   .height = target.height,
                                   .format = rhi::Format::D32F,
                                   .usage = rhi::TextureUsage::RenderTarget,
                                   .debugName = "pattern.depth"})),
      uniforms_(device.createBuffer(
          {.size = sizeof(PatternUniforms), .usage = rhi::BufferUsage::Uniform, .debugName = "pattern.uniforms"})),
      commands_(device.createCommandList())
{
    const rhi::Attachment colorAttachment{color_.get(), 0};
    framebuffer_ =
        device.createFramebuffer({.colors = {&colorAttachment, 1}, .depth = {depth_.get(), 0}, .debugName = "pattern"});
    uniforms_->writeObject(PatternUniforms{projection_});
}

const rhi::Pipeline& PatternRenderer::pipeline(rhi::CullMode cull)
{
    for (const auto& [mode, pipeline] : pipelines_)
        if (mode == cull)
            return *pipeline;
    rhi::PipelineDesc desc{
        .vertex = vertexShader_.get(),
        .fragment = fragmentShader_.get(),
        .vertexLayout = {.buffers = {{.stride = sizeof(PatternVertex)}},
                         .attributes = {{.location = 0, .format = rhi::VertexFormat::Float3, .offset = 0},
                                        {.location = 1,
                                         .format = rhi::VertexFormat::Float4,
                                         .offset = offsetof(PatternVertex, color)}}},
        .cull = cull,
        .depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer},
        .colorTargets = {{.format = rhi::Format::RGBA8}},
        .depthFormat = rhi::Format::D32F,
        .uniformLayouts = {shaders::uniformLayout(kPatternBlock)},
        .debugName = "pattern",
    };
    pipelines_.emplace_back(cull, device_.createPipeline(desc));
    return *pipelines_.back().second;
}

void PatternRenderer::render(std::span<const PatternVertex> triangles, rhi::CullMode cull)
{
    commands_->beginPass({.framebuffer = framebuffer_.get(), .clearColor = glm::vec4(0, 0, 0, 1)});
    if (!triangles.empty()) {
        const std::uint64_t size = triangles.size_bytes();
        if (!vertices_ || vertices_->desc().size < size)
            vertices_ = device_.createBuffer(
                {.size = size, .usage = rhi::BufferUsage::Vertex, .debugName = "pattern.vertices"});
        vertices_->write(0, std::as_bytes(triangles));
        commands_->bindPipeline(pipeline(cull));
        commands_->bindUniformBuffer(kPatternBinding, *uniforms_, 0, sizeof(PatternUniforms));
        commands_->bindVertexBuffer(0, *vertices_);
        commands_->draw(std::uint32_t(triangles.size()));
    }
    commands_->endPass();
    device_.submit(*commands_);
}

rhi::Image PatternRenderer::color() const { return rhi::readTexture(device_, *color_); }

rhi::DepthImage PatternRenderer::depth() const { return rhi::readDepth(device_, *depth_); }

} // namespace penumbra::pattern
