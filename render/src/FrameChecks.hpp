#pragma once

#include "penumbra/render/SceneRenderer.hpp"

// The checks of SceneRenderer::render's input; each throws rhi::Error (rhi::UnsupportedError for an msaa count the
// device does not offer) naming the field.
namespace penumbra::render {

void checkFrameSize(const FrameDesc& frame);
// A plan drawn into atlases of other sizes would put its tiles in the wrong texels.
void checkPlansFitFrame(const ShadowPlans& plans, const shadows::ShadowSettings& settings);
// FrameDesc::msaa: 1, or a count the device offers for both of the lit pass's targets.
void checkMsaa(const FrameDesc& frame, const rhi::Capabilities& caps);
void checkShadowPath(const FrameDesc& frame);

} // namespace penumbra::render
