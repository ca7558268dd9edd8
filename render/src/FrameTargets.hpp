#pragma once

#include "penumbra/render/SceneRenderer.hpp"

namespace penumbra::render {

// The lit depth target's description with `samples` samples; single-sampled, the screen-space shadow collection
// samples it too.
rhi::TextureDesc depthTargetDesc(const FrameDesc& frame, std::uint32_t samples);

} // namespace penumbra::render
