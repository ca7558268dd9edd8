#pragma once

#include "penumbra/rhi/Device.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <memory>

namespace penumbra::apps {

// How the draw-call benchmark draws each cube: drawIndexed, or drawIndexedIndirect with the cube's arguments read on
// the GPU from DrawScene::indirectArguments.
enum class DrawCall { Direct, Indirect };

// mesh.vert's uniform block Object (std140): one cube's transform and colour.
struct DrawObjectUniforms {
    glm::mat4 modelViewProjection{1.0f};
    glm::vec4 color{0.0f};
};

// The draw-call benchmark's scene: `count` small cubes, each with its own transform and colour
// in one uniform buffer (one aligned block per cube), drawn into a small RGBA8 + D32F target.
// The RHI path and the raw-API paths draw exactly these objects.
class DrawScene {
public:
    DrawScene(rhi::Device& device, std::uint32_t count);

    // One frame through the RHI: clear, then one bindUniformBuffer and one draw per cube, as `call` says.
    void recordRhi(rhi::CommandList& commands, DrawCall call) const;

    std::uint32_t count() const { return count_; }
    std::uint32_t indexCount() const { return 36; }
    std::uint64_t objectStride() const { return objectStride_; }
    static constexpr std::uint32_t objectSize = sizeof(DrawObjectUniforms);
    static constexpr std::uint32_t size = 128; // target width and height
    // Bytes per cube in indirectArguments(): VkDrawIndexedIndirectCommand, GL's DrawElementsIndirectCommand.
    static constexpr std::uint32_t indirectStride = 20;

    const rhi::Pipeline& pipeline() const { return *pipeline_; }
    const rhi::Framebuffer& framebuffer() const { return *framebuffer_; }
    const rhi::Buffer& vertices() const { return *vertices_; }
    const rhi::Buffer& indices() const { return *indices_; }
    const rhi::Buffer& objects() const { return *objects_; }
    const rhi::Buffer& indirectArguments() const { return *indirectArguments_; }
    const rhi::Texture& color() const { return *color_; }

private:
    std::uint32_t count_;
    std::uint64_t objectStride_;
    std::unique_ptr<rhi::Shader> vertexShader_, fragmentShader_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
    std::unique_ptr<rhi::Texture> color_, depth_;
    std::unique_ptr<rhi::Framebuffer> framebuffer_;
    std::unique_ptr<rhi::Buffer> vertices_, indices_, objects_, indirectArguments_;
};

} // namespace penumbra::apps
