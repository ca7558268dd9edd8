#pragma once

#include "penumbra/render/SceneRenderer.hpp"

namespace penumbra::render {

// The lit depth target's description with `samples` samples; single-sampled, the screen-space shadow collection
// samples it too.
rhi::TextureDesc depthTargetDesc(const FrameDesc& frame, std::uint32_t samples);

class ContactShadowPass;
class DepthPrepass;
class FrameGraph;

// FrameDesc::msaa > 1: the multisampled colour and depth that live within the frame.
void createMultisampledTargets(FrameGraph& graph, const FrameDesc& frame);

// shadows.contact: the march and its target for the frame's size, and with MSAA the single-sampled prepass it
// marches through on the forward path; each made when a frame first needs it.
void prepareContactShadows(rhi::Device& device, const FrameDesc& frame, std::unique_ptr<ContactShadowPass>& contact);

} // namespace penumbra::render
