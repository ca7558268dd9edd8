#pragma once

#include "GpuSkinning.hpp"

#include "penumbra/render/FramePass.hpp"

namespace penumbra::render {

// The frame's first pass where the scene has deformed meshes: GpuSkinning poses them into the vertex buffers that
// every later pass draws (frame::kPosedVertices, a storage write here, a vertex read in the passes that draw).
class SkinningPass final : public FramePass {
public:
    explicit SkinningPass(GpuSkinning& skinning) : skinning_(skinning) {}
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    GpuSkinning& skinning_;
};

} // namespace penumbra::render
