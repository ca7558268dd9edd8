#include "DrawScene.hpp"

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace penumbra::apps {
namespace {

constexpr std::uint32_t kObjectBinding = 0;
constexpr std::array kDrawObjectFields{PENUMBRA_SHADER_FIELD(DrawObjectUniforms, modelViewProjection),
                                       PENUMBRA_SHADER_FIELD(DrawObjectUniforms, color)};
constexpr shaders::ShaderStruct kDrawObjectBlock{"Object", sizeof(DrawObjectUniforms), kDrawObjectFields};
static_assert(shaders::matchesLayout(kDrawObjectBlock, shaders::BlockLayout::Std140));

rhi::ShaderSource meshVertexShader()
{
    rhi::ShaderSource source = shaders::load("mesh.vert");
    source.includes.push_back(
        {"mesh_blocks.glsl", shaders::uniformBlockGlsl(kDrawObjectBlock, kObjectBinding, "object")});
    return source;
}

} // namespace

DrawScene::DrawScene(rhi::Device& device, std::uint32_t count)
    : count_(count), objectStride_((objectSize + device.capabilities().uniformBufferOffsetAlignment - 1) /
                                   device.capabilities().uniformBufferOffsetAlignment *
                                   device.capabilities().uniformBufferOffsetAlignment),
      vertexShader_(device.createShader(meshVertexShader())),
      fragmentShader_(device.createShader(shaders::load("mesh.frag")))
{
    pipeline_ = device.createPipeline({
        .vertex = vertexShader_.get(),
        .fragment = fragmentShader_.get(),
        .vertexLayout = {.buffers = {{.stride = sizeof(glm::vec3)}},
                         .attributes = {{.location = 0, .format = rhi::VertexFormat::Float3}}},
        .cull = rhi::CullMode::Back,
        .depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer},
        .colorTargets = {{.format = rhi::Format::RGBA8}},
        .depthFormat = rhi::Format::D32F,
        .uniformLayouts = {shaders::uniformLayout(kDrawObjectBlock)},
        .debugName = "mesh",
    });
    color_ = device.createTexture({.width = size,
                                   .height = size,
                                   .format = rhi::Format::RGBA8,
                                   .usage = rhi::TextureUsage::RenderTarget,
                                   .debugName = "bench.color"});
    depth_ = device.createTexture({.width = size,
                                   .height = size,
                                   .format = rhi::Format::D32F,
                                   .usage = rhi::TextureUsage::RenderTarget,
                                   .debugName = "bench.depth"});
    const rhi::Attachment colorAttachment{color_.get(), 0};
    framebuffer_ = device.createFramebuffer({.colors = {&colorAttachment, 1}, .depth = {depth_.get(), 0}});

    const std::array<glm::vec3, 8> corners = {
        {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};
    // Counter-clockwise seen from outside the cube.
    const std::array<std::uint16_t, 36> faces = {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                                 3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
    vertices_ = device.createBuffer({.size = sizeof(corners), .usage = rhi::BufferUsage::Vertex, .debugName = "cube"});
    vertices_->write(0, std::as_bytes(std::span(corners)));
    indices_ = device.createBuffer({.size = sizeof(faces), .usage = rhi::BufferUsage::Index, .debugName = "cube"});
    indices_->write(0, std::as_bytes(std::span(faces)));

    // A grid of small spinning cubes filling the view, each a few pixels wide.
    objects_ = device.createBuffer(
        {.size = objectStride_ * count, .usage = rhi::BufferUsage::Uniform, .debugName = "objects"});
    const glm::mat4 projection = device.conventions().perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
    const std::uint32_t side = std::uint32_t(std::ceil(std::sqrt(double(count))));
    std::vector<std::byte> blocks(objectStride_ * count);
    for (std::uint32_t i = 0; i < count; ++i) {
        const float u = (float(i % side) + 0.5f) / float(side) * 2.0f - 1.0f;
        const float v = (float(i / side) + 0.5f) / float(side) * 2.0f - 1.0f;
        glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(u * 5.0f, v * 5.0f, -9.0f));
        model = glm::rotate(model, float(i) * 0.37f, glm::normalize(glm::vec3(1, 1, 0)));
        model = glm::scale(model, glm::vec3(2.0f / float(side)));
        const DrawObjectUniforms object{projection * model, glm::vec4(u * 0.5f + 0.5f, v * 0.5f + 0.5f, 0.5f, 1.0f)};
        std::memcpy(blocks.data() + objectStride_ * i, &object, objectSize);
    }
    objects_->write(0, blocks);

    // indexCount, instanceCount, firstIndex, vertexOffset, firstInstance: the cube once, as drawIndexed draws it.
    const std::vector<std::array<std::uint32_t, 5>> arguments(count, {indexCount(), 1, 0, 0, 0});
    static_assert(sizeof(arguments[0]) == indirectStride);
    indirectArguments_ = device.createBuffer({.size = std::uint64_t(indirectStride) * count,
                                              .usage = rhi::BufferUsage::Indirect,
                                              .debugName = "indirect arguments"});
    indirectArguments_->write(0, std::as_bytes(std::span(arguments)));
}

void DrawScene::recordRhi(rhi::CommandList& commands, DrawCall call) const
{
    commands.beginPass({.framebuffer = framebuffer_.get()});
    commands.bindPipeline(*pipeline_);
    commands.bindVertexBuffer(0, *vertices_);
    commands.bindIndexBuffer(*indices_, rhi::IndexType::UInt16);
    for (std::uint32_t i = 0; i < count_; ++i) {
        commands.bindUniformBuffer(kObjectBinding, *objects_, objectStride_ * i, objectSize);
        if (call == DrawCall::Indirect)
            commands.drawIndexedIndirect(*indirectArguments_, std::uint64_t(indirectStride) * i);
        else
            commands.drawIndexed(indexCount());
    }
    commands.endPass();
}

} // namespace penumbra::apps
