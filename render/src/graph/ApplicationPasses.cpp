#include "ApplicationPasses.hpp"

#include "FrameGraph.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::render {

void ApplicationPasses::addPass(std::shared_ptr<FramePass> pass, PassPlacement placement)
{
    if (!pass)
        throw rhi::Error("SceneRenderer::addPass: no pass");
    if (std::find(frame::kPasses.begin(), frame::kPasses.end(), placement.pass) == frame::kPasses.end()) {
        std::string names;
        for (std::string_view name : frame::kPasses)
            names += fmt::format("{}'{}'", names.empty() ? "" : ", ", name);
        throw rhi::Error(fmt::format("SceneRenderer::addPass: pass '{}' is placed {} '{}', which is not a pass of the "
                                     "frame ({})",
                                     pass->name(), placement.side == PassPlacement::Side::Before ? "before" : "after",
                                     placement.pass, names));
    }
    passes_.push_back({std::move(pass), std::move(placement)});
}

void ApplicationPasses::addTexture(std::string name, const rhi::Texture& texture)
{
    textures_.push_back({std::move(name), texture});
}

void ApplicationPasses::addBuffer(std::string name, const rhi::Buffer& buffer)
{
    buffers_.push_back({std::move(name), buffer});
}

void ApplicationPasses::importResources(FrameGraph& graph) const
{
    for (const NamedTexture& texture : textures_)
        graph.importTexture(texture.name, texture.texture, true);
    for (const NamedBuffer& buffer : buffers_)
        graph.importBuffer(buffer.name, buffer.buffer, true);
}

void ApplicationPasses::addAround(FrameGraph& graph, FramePass& pass) const
{
    const std::string name = pass.name();
    addPlaced(graph, name, PassPlacement::Side::Before);
    graph.addPass(pass);
    addPlaced(graph, name, PassPlacement::Side::After);
}

void ApplicationPasses::addPlaced(FrameGraph& graph, const std::string& pass, PassPlacement::Side side) const
{
    for (const Placed& placed : passes_)
        if (placed.placement.pass == pass && placed.placement.side == side)
            graph.addPass(*placed.pass);
}

} // namespace penumbra::render
