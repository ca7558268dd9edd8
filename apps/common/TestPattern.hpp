#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/rhi/Shader.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <span>
#include <vector>

namespace penumbra::pattern {

// A vertex of shaders/pattern.vert: x, y in canonical NDC (y up), z the view depth, and a colour.
struct PatternVertex {
    glm::vec3 position;
    glm::vec4 color;
};

// pattern.vert's uniform block Pattern (std140): the projection of the view depths.
struct PatternUniforms {
    glm::mat4 projection{1.0f};
};

// pattern.vert with its block Pattern (PatternUniforms) at binding 0, generated from the C++ declaration.
rhi::ShaderSource patternVertexShader();

// The demo picture: overlapping triangles at several depths, a red marker at the top-left,
// a green one at the top-right and a blue one at the bottom-left, so any flip or depth mistake shows.
std::vector<PatternVertex> testPattern();

struct PatternTarget {
    std::uint32_t width = 64;
    std::uint32_t height = 64;
    float zNear = 0.1f;
    float zFar = 100.0f;
    bool sampled = false; // the colour target can also be sampled (colorTexture())
};

// Draws PatternVertex triangle lists into an RGBA8 + D32F target through any rhi::Device.
class PatternRenderer {
public:
    PatternRenderer(rhi::Device& device, const PatternTarget& target);

    // Clears, then draws the triangle list with the given cull mode (depth test Nearer, write on).
    void render(std::span<const PatternVertex> triangles, rhi::CullMode cull = rhi::CullMode::None);

    rhi::Image color() const;
    const rhi::Texture& colorTexture() const { return *color_; }
    rhi::DepthImage depth() const;
    // The projection whose depth row places view depth into this device's convention.
    const glm::mat4& projection() const { return projection_; }

private:
    const rhi::Pipeline& pipeline(rhi::CullMode cull);

    rhi::Device& device_;
    PatternTarget target_;
    glm::mat4 projection_;
    std::unique_ptr<rhi::Shader> vertexShader_;
    std::unique_ptr<rhi::Shader> fragmentShader_;
    std::vector<std::pair<rhi::CullMode, std::unique_ptr<rhi::Pipeline>>> pipelines_;
    std::unique_ptr<rhi::Texture> color_;
    std::unique_ptr<rhi::Texture> depth_;
    std::unique_ptr<rhi::Framebuffer> framebuffer_;
    std::unique_ptr<rhi::Buffer> uniforms_;
    std::unique_ptr<rhi::Buffer> vertices_;
    std::unique_ptr<rhi::CommandList> commands_;
};

} // namespace penumbra::pattern
