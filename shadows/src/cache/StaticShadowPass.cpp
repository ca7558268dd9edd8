#include "penumbra/shadows/StaticShadowPass.hpp"

#include "penumbra/shaders/ShaderLibrary.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {

StaticShadowPass::StaticShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat)
    : device_(device), draws_(device, vertexFormat),
      clearVertex_(device.createShader(shaders::load("fullscreen.vert"))),
      clearFragment_(device.createShader(shaders::load("depth_clear.frag")))
{
}

const rhi::Pipeline& StaticShadowPass::clearPipeline(rhi::Format format)
{
    std::unique_ptr<rhi::Pipeline>& pipeline = clearPipelines_[format];
    if (!pipeline) {
        rhi::PipelineDesc desc;
        desc.vertex = clearVertex_.get();
        desc.fragment = clearFragment_.get();
        desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Always};
        desc.depthFormat = format;
        desc.debugName = fmt::format("static shadow tile clear ({})", rhi::formatName(format));
        pipeline = device_.createPipeline(desc);
    }
    return *pipeline;
}

std::uint32_t StaticShadowPass::record(rhi::CommandList& commands, const ShadowAtlas& atlas,
                                       std::span<const ShadowTileDraw* const> tiles,
                                       std::span<const ShadowCaster> casters, bool clearAll)
{
    std::uint32_t draws = 0;
    commands.beginPass({.framebuffer = &atlas.framebuffer(), .clearColor = std::nullopt, .clearDepth = clearAll});
    const rhi::Pipeline& clear = clearPipeline(atlas.format());
    for (const ShadowTileDraw* tile : tiles) {
        commands.setViewport(tile->viewport);
        commands.setScissor(scissorOf(tile->viewport));
        if (!clearAll) {
            commands.bindPipeline(clear);
            commands.draw(3);
        }
        draws += draws_.draw(commands, atlas.format(), tile->view, tile->casters, casters);
    }
    commands.endPass();
    return draws;
}

} // namespace penumbra::shadows
