#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/DepthFit.hpp"

#include <glm/mat4x4.hpp>
#include <memory>
#include <optional>

namespace penumbra::render {

// The depth fit's reduction (shaders/depth_reduction.comp): the nearest and farthest depth of the pixels a
// single-sampled depth texture holds, into a two-word storage buffer. The renderer reads it after the frame's
// submission (which already waits for the GPU), so the next frame plans with it and none waits for it.
class DepthReduction {
public:
    explicit DepthReduction(rhi::Device& device);

    // Resets the buffer and records the dispatch over `depth` (single-sampled, sampled, the frame's lit depth).
    void record(rhi::CommandList& commands, const rhi::Texture& depth);
    // After the submission: the view depths of the nearest and farthest pixel drawn, through the frame's `projection`;
    // nullopt where no pixel was drawn or nothing was recorded since the last read.
    std::optional<shadows::ViewDepthRange> read(const rhi::Conventions& conventions, const glm::mat4& projection);

private:
    std::unique_ptr<rhi::ComputePipeline> pipeline_;
    std::unique_ptr<rhi::Sampler> sampler_;
    std::unique_ptr<rhi::Buffer> bounds_;
    bool recorded_ = false;
};

} // namespace penumbra::render
