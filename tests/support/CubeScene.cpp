#include "CubeScene.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::testing {

CubeFaceFrame cubeFaceFrame(rhi::CubeFace face)
{
    const int axis = int(face) / 2;
    const float sign = int(face) % 2 ? -1.0f : 1.0f;
    glm::vec3 a(0.0f), b(0.0f), c(0.0f);
    a[axis] = sign;
    b[(axis + 1) % 3] = 1.0f;
    c[(axis + 2) % 3] = 1.0f;
    return {a, b, c};
}

rhi::CubeFace majorFace(const glm::vec3& d)
{
    const glm::vec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return rhi::CubeFace(2 * axis + (d[axis] < 0.0f ? 1 : 0));
}

glm::vec3 cubeTexelDirection(rhi::CubeFace face, std::uint32_t x, std::uint32_t y, std::uint32_t size)
{
    const float sc = 2.0f * (float(x) + 0.5f) / float(size) - 1.0f;
    const float tc = 2.0f * (float(y) + 0.5f) / float(size) - 1.0f;
    switch (face) {
    case rhi::CubeFace::PositiveX:
        return {1.0f, -tc, -sc};
    case rhi::CubeFace::NegativeX:
        return {-1.0f, -tc, sc};
    case rhi::CubeFace::PositiveY:
        return {sc, 1.0f, tc};
    case rhi::CubeFace::NegativeY:
        return {sc, -1.0f, -tc};
    case rhi::CubeFace::PositiveZ:
        return {sc, -tc, 1.0f};
    case rhi::CubeFace::NegativeZ:
        return {-sc, -tc, -1.0f};
    }
    return {};
}

void addCubeQuad(std::vector<CubeVertex>& out, const glm::vec3& centre, rhi::CubeFace face, float distance,
                 glm::vec2 bRange, glm::vec2 cRange, const glm::vec4& color, bool facingCentre)
{
    const CubeFaceFrame f = cubeFaceFrame(face);
    auto corner = [&](float b, float c) { return centre + distance * (f.axis + b * f.b + c * f.c); };
    glm::vec3 p[4] = {corner(bRange[0], cRange[0]), corner(bRange[1], cRange[0]), corner(bRange[1], cRange[1]),
                      corner(bRange[0], cRange[1])};
    const glm::vec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
    const bool towardsCentre = glm::dot(normal, centre - p[0]) > 0.0f;
    if (towardsCentre != facingCentre)
        std::swap(p[1], p[3]);
    for (int i : {0, 1, 2, 0, 2, 3})
        out.push_back({p[i], color});
}

CubeFaceRenderer::CubeFaceRenderer(rhi::Device& device, rhi::Format format, float zNear, float zFar)
    : device_(device), projection_(rhi::cubeFaceProjection(device.conventions(), zNear, zFar))
{
    vertex_ = device.createShader({rhi::ShaderStage::Vertex, R"(#version 450
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;
layout(std140, binding = 0) uniform Face { mat4 viewProjection; } face;
layout(location = 0) out vec4 vColor;
void main() { vColor = color; gl_Position = face.viewProjection * vec4(position, 1.0); }
)",
                                   "cube_face.vert"});
    const bool depth = rhi::isDepthFormat(format);
    fragment_ =
        device.createShader({rhi::ShaderStage::Fragment, depth ? "#version 450\nvoid main() {}\n" : R"(#version 450
layout(location = 0) in vec4 vColor;
layout(location = 0) out vec4 outColor;
void main() { outColor = vColor; }
)",
                             "cube_face.frag"});
    rhi::PipelineDesc desc{
        .vertex = vertex_.get(),
        .fragment = fragment_.get(),
        .vertexLayout = {.buffers = {{.stride = sizeof(CubeVertex)}},
                         .attributes = {{.location = 0, .format = rhi::VertexFormat::Float3},
                                        {.location = 1,
                                         .format = rhi::VertexFormat::Float4,
                                         .offset = offsetof(CubeVertex, color)}}},
        .cull = rhi::cubeFaceCullMode(rhi::CullMode::Back),
        .debugName = "cube faces",
    };
    if (depth) {
        desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer};
        desc.depthFormat = format;
    } else {
        desc.colorTargets = {{.format = format}};
    }
    pipeline_ = device.createPipeline(desc);
}

void CubeFaceRenderer::render(const rhi::Texture& cubeTexture, std::uint32_t cube, const glm::vec3& centre,
                              std::span<const CubeVertex> triangles)
{
    const std::uint64_t alignment = device_.capabilities().uniformBufferOffsetAlignment;
    const std::uint64_t stride = (sizeof(glm::mat4) + alignment - 1) / alignment * alignment;
    auto uniforms = device_.createBuffer({.size = 6 * stride, .usage = rhi::BufferUsage::Uniform});
    auto vertices = device_.createBuffer({.size = triangles.size_bytes(), .usage = rhi::BufferUsage::Vertex});
    vertices->write(0, std::as_bytes(triangles));
    const bool depth = rhi::isDepthFormat(cubeTexture.desc().format);
    std::vector<std::unique_ptr<rhi::Framebuffer>> framebuffers;
    auto commands = device_.createCommandList();
    for (rhi::CubeFace face : rhi::allCubeFaces) {
        const std::uint32_t index = std::uint32_t(face);
        uniforms->writeObject(projection_ * rhi::cubeFaceView(face, centre), index * stride);
        const rhi::Attachment attachment{&cubeTexture, rhi::cubeLayer(cube, face)};
        framebuffers.push_back(depth ? device_.createFramebuffer({.depth = attachment})
                                     : device_.createFramebuffer({.colors = {&attachment, 1}}));
        commands->beginPass({.framebuffer = framebuffers.back().get(),
                             .clearColor = depth ? std::nullopt : std::optional(glm::vec4(0.0f))});
        commands->bindPipeline(*pipeline_);
        commands->bindUniformBuffer(0, *uniforms, index * stride, sizeof(glm::mat4));
        commands->bindVertexBuffer(0, *vertices);
        commands->draw(std::uint32_t(triangles.size()));
        commands->endPass();
    }
    device_.submit(*commands);
}

rhi::Image sampleCubeProbes(rhi::Device& device, const rhi::Texture& cubeTexture, const rhi::Sampler& sampler,
                            const std::string& samplerType, const std::string& fragmentBody,
                            std::span<const glm::vec4> directions, std::span<const float> references)
{
    const std::size_t count = directions.size();
    std::vector<glm::vec4> block(directions.begin(), directions.end());
    for (std::size_t i = 0; i < count; ++i)
        block.emplace_back(i < references.size() ? references[i] : 0.0f, 0.0f, 0.0f, 0.0f);
    auto uniforms = device.createBuffer({.size = block.size() * sizeof(glm::vec4), .usage = rhi::BufferUsage::Uniform});
    uniforms->write(0, std::as_bytes(std::span(block)));
    auto vertex = device.createShader(shaders::load("fullscreen.vert"));
    auto fragment = device.createShader({rhi::ShaderStage::Fragment,
                                         fmt::format(R"(#version 450
layout(std140, binding = 0) uniform Probes {{ vec4 direction[{0}]; vec4 reference[{0}]; }} probe;
layout(binding = 1) uniform {1} cubeTexture;
layout(location = 0) out vec4 outColor;
void main() {{ int i = int(gl_FragCoord.x); {2} }}
)",
                                                     count, samplerType, fragmentBody),
                                         "cube_probes.frag"});
    auto pipeline = device.createPipeline(
        {.vertex = vertex.get(), .fragment = fragment.get(), .colorTargets = {{.format = rhi::Format::RGBA8}}});
    auto target = device.createTexture(
        {.width = std::uint32_t(count), .height = 1, .usage = rhi::TextureUsage::RenderTarget, .debugName = "probes"});
    const rhi::Attachment attachment{target.get(), 0};
    auto framebuffer = device.createFramebuffer({.colors = {&attachment, 1}});
    auto commands = device.createCommandList();
    commands->beginPass({.framebuffer = framebuffer.get()});
    commands->bindPipeline(*pipeline);
    commands->bindUniformBuffer(0, *uniforms, 0, uniforms->desc().size);
    commands->bindTexture(1, cubeTexture, sampler);
    commands->draw(3);
    commands->endPass();
    device.submit(*commands);
    return rhi::readTexture(device, *target);
}

rhi::Image cubeStrip(rhi::Device& device, const rhi::Texture& cubeTexture, std::uint32_t cube)
{
    const rhi::TextureDesc& d = cubeTexture.desc();
    const std::size_t texel = rhi::texelSize(d.format);
    rhi::Image strip{6 * d.width, d.height, d.format, std::vector<std::byte>(6 * d.width * d.height * texel)};
    for (rhi::CubeFace face : rhi::allCubeFaces) {
        const rhi::Image image = rhi::readTexture(device, cubeTexture, rhi::cubeLayer(cube, face));
        for (std::uint32_t y = 0; y < d.height; ++y)
            std::memcpy(strip.bytes.data() + (std::size_t(y) * strip.width + std::size_t(face) * d.width) * texel,
                        image.texel(0, y), d.width * texel);
    }
    return strip;
}

} // namespace penumbra::testing
