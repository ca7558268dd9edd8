#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"

#include <memory>

struct ImDrawData;

namespace penumbra::viewer {

// Draws Dear ImGui's draw lists through the RHI, so the panel looks the same on every backend:
// the font atlas as an RGBA8 texture, one vertex and one index buffer per frame (grown as
// needed), one indexed draw per command with its clip rectangle as scissor, straight-alpha
// blending. ImTextureID is a `const rhi::Texture*`; the font atlas's id is set here.
class ImGuiRenderer {
public:
    // Needs a current ImGui context whose fonts are added; uploads the font atlas.
    ImGuiRenderer(rhi::Device& device, rhi::Format targetFormat);

    // Records the draws into the open pass of a target of the draw data's display size.
    // Buffers are rewritten each frame: submit before the next record().
    void record(rhi::CommandList& commands, const ImDrawData& drawData);

private:
    void reserve(std::size_t vertexBytes, std::size_t indexBytes);

    rhi::Device& device_;
    std::unique_ptr<rhi::Shader> vertex_;
    std::unique_ptr<rhi::Shader> fragment_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
    std::unique_ptr<rhi::Texture> font_;
    std::unique_ptr<rhi::Sampler> sampler_;
    std::unique_ptr<rhi::Buffer> vertices_;
    std::unique_ptr<rhi::Buffer> indices_;
    rhi::UniformArena uniforms_;
};

} // namespace penumbra::viewer
