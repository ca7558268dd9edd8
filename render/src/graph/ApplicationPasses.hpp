#pragma once

#include "penumbra/render/FramePass.hpp"
#include "penumbra/rhi/Resources.hpp"

#include <memory>
#include <string>
#include <vector>

namespace penumbra::render {

class FrameGraph;

// What an application adds to the frame (SceneRenderer::addPass, addTexture, addBuffer): checked when added, then put
// into every frame's graph beside the built-in passes.
class ApplicationPasses {
public:
    // Throws rhi::Error for no pass or a placement naming no built-in pass (frame::kPasses).
    void addPass(std::shared_ptr<FramePass> pass, PassPlacement placement);
    void addTexture(std::string name, const rhi::Texture& texture);
    void addBuffer(std::string name, const rhi::Buffer& buffer);

    // The application's textures and buffers, as frame outputs: the passes that lead to them are never culled.
    void importResources(FrameGraph& graph) const;
    // The built-in `pass`, with the application's passes placed before and after it, each side in the order added.
    void addAround(FrameGraph& graph, FramePass& pass) const;

private:
    struct Placed {
        std::shared_ptr<FramePass> pass;
        PassPlacement placement;
    };
    struct NamedTexture {
        std::string name;
        const rhi::Texture& texture;
    };
    struct NamedBuffer {
        std::string name;
        const rhi::Buffer& buffer;
    };

    void addPlaced(FrameGraph& graph, const std::string& pass, PassPlacement::Side side) const;

    std::vector<Placed> passes_;
    std::vector<NamedTexture> textures_;
    std::vector<NamedBuffer> buffers_;
};

} // namespace penumbra::render
