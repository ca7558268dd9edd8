#pragma once

// A pass of one's own on the RHI, as a user would write it: a full-screen gradient, then two
// triangles that cross each other in depth, drawn with the depth test, into an RGBA8 + D32F target.
// custom_pass.cpp writes its picture; custom_pass_parity_test.cpp proves it renders the same on
// every configuration with penumbra::parity.

#include <penumbra/rhi/Device.hpp>
#include <penumbra/rhi/Image.hpp>

#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <memory>

namespace examples {

class CustomPass {
public:
    CustomPass(penumbra::rhi::Device& device, std::uint32_t width, std::uint32_t height)
        : device_(device),
          // The device's conventions give the projection for its depth range and direction.
          projection_(device.conventions().perspective(glm::radians(60.0f), float(width) / float(height), 0.1f, 100.0f))
    {
        using namespace penumbra::rhi;
        color_ = device.createTexture({.width = width, .height = height, .usage = TextureUsage::RenderTarget});
        depth_ = device.createTexture(
            {.width = width, .height = height, .format = Format::D32F, .usage = TextureUsage::RenderTarget});
        const Attachment colour{color_.get(), 0};
        framebuffer_ = device.createFramebuffer({.colors = {&colour, 1}, .depth = {depth_.get(), 0}});

        gradientVertex_ = device.createShader({ShaderStage::Vertex, R"(#version 450
            // One triangle over the whole screen; uv runs 0..1 across the visible part.
            const vec2 corners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
            layout(location = 0) out vec2 uv;
            void main() { uv = corners[gl_VertexIndex] * 0.5 + 0.5; gl_Position = vec4(corners[gl_VertexIndex], 0.0, 1.0); })"});
        gradientFragment_ = device.createShader({ShaderStage::Fragment, R"(#version 450
            layout(location = 0) in vec2 uv;
            layout(location = 0) out vec4 result;
            void main() { result = vec4(uv.x, uv.y, 1.0 - uv.x, 1.0); })"});
        gradient_ = device.createPipeline({.vertex = gradientVertex_.get(),
                                           .fragment = gradientFragment_.get(),
                                           .colorTargets = {{}},
                                           .depthFormat = Format::D32F});

        trianglesVertex_ = device.createShader({ShaderStage::Vertex, R"(#version 450
            layout(std140, binding = 0) uniform View { mat4 projection; } view;
            layout(location = 0) in vec3 position; // view space, the camera looking down -z
            layout(location = 1) in vec4 colour;
            layout(location = 0) out vec4 vColour;
            void main() { gl_Position = view.projection * vec4(position, 1.0); vColour = colour; })"});
        trianglesFragment_ = device.createShader({ShaderStage::Fragment, R"(#version 450
            layout(location = 0) in vec4 vColour;
            layout(location = 0) out vec4 result;
            void main() { result = vColour; })"});
        triangles_ = device.createPipeline({
            .vertex = trianglesVertex_.get(),
            .fragment = trianglesFragment_.get(),
            .vertexLayout =
                {.buffers = {{.stride = sizeof(Vertex)}},
                 .attributes = {{.location = 0, .format = VertexFormat::Float3, .offset = 0},
                                {.location = 1, .format = VertexFormat::Float4, .offset = offsetof(Vertex, colour)}}},
            .depth = {.test = true, .write = true, .compare = DepthTest::Nearer},
            .colorTargets = {{}},
            .depthFormat = Format::D32F,
        });
        // Orange leans away to the right, blue away to the left: the depth test draws the seam where they cross.
        const std::array<Vertex, 6> vertices{{{{-1.2f, -0.9f, -3.0f}, {1.0f, 0.55f, 0.1f, 1.0f}},
                                              {{1.2f, -0.9f, -5.0f}, {1.0f, 0.55f, 0.1f, 1.0f}},
                                              {{0.0f, 1.0f, -4.0f}, {1.0f, 0.55f, 0.1f, 1.0f}},
                                              {{-1.2f, -0.7f, -5.0f}, {0.1f, 0.3f, 1.0f, 1.0f}},
                                              {{1.2f, -0.7f, -3.0f}, {0.1f, 0.3f, 1.0f, 1.0f}},
                                              {{0.0f, 1.2f, -4.0f}, {0.1f, 0.3f, 1.0f, 1.0f}}}};
        vertices_ = device.createBuffer({.size = sizeof(vertices), .usage = BufferUsage::Vertex});
        vertices_->writeObject(vertices);
        uniforms_ = device.createBuffer({.size = sizeof(glm::mat4), .usage = BufferUsage::Uniform});
        uniforms_->writeObject(projection_);
    }

    void render()
    {
        auto commands = device_.createCommandList();
        commands->beginPass({.framebuffer = framebuffer_.get()}); // colour cleared to black, depth to the far plane
        commands->bindPipeline(*gradient_);
        commands->draw(3);
        commands->bindPipeline(*triangles_);
        commands->bindUniformBuffer(0, *uniforms_, 0, sizeof(glm::mat4));
        commands->bindVertexBuffer(0, *vertices_);
        commands->draw(6);
        commands->endPass();
        device_.submit(*commands);
    }

    penumbra::rhi::Image color() const { return penumbra::rhi::readTexture(device_, *color_); }
    penumbra::rhi::DepthImage depth() const { return penumbra::rhi::readDepth(device_, *depth_); }
    // The projection the triangles' depth was written through.
    const glm::mat4& projection() const { return projection_; }

private:
    struct Vertex {
        glm::vec3 position;
        glm::vec4 colour;
    };

    penumbra::rhi::Device& device_;
    glm::mat4 projection_;
    std::unique_ptr<penumbra::rhi::Texture> color_, depth_;
    std::unique_ptr<penumbra::rhi::Framebuffer> framebuffer_;
    std::unique_ptr<penumbra::rhi::Shader> gradientVertex_, gradientFragment_, trianglesVertex_, trianglesFragment_;
    std::unique_ptr<penumbra::rhi::Pipeline> gradient_, triangles_;
    std::unique_ptr<penumbra::rhi::Buffer> vertices_, uniforms_;
};

} // namespace examples
