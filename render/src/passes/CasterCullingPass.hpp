#pragma once

#include "FrameState.hpp"

#include "penumbra/render/FramePass.hpp"
#include "penumbra/render/GpuScene.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/GpuCasterCulling.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"

namespace penumbra::render {

// ShadowSettings::culling gpu: uploads every caster and every realtime atlas tile's volume (the directional cascades,
// then the local atlas tiles) for GpuCasterCulling, before the frame's graph is built, which then holds its buffers.
void prepareCasterCulling(shadows::GpuCasterCulling& culling, std::span<const shadows::ShadowCaster> casters,
                          const GpuScene& scene, const shadows::DirectionalShadowPlan& plan,
                          const shadows::LocalShadowPlan& localPlan);

// ShadowSettings::culling gpu: every caster tested against every tile's volume in one dispatch, whose instance lists
// and indirect draws (frame::kCulledInstances, kCulledDraws) the atlas passes draw (FrameState::culling). The planner
// leaves those tiles' lists empty; cube-map faces stay culled by the planner.
class CasterCullingPass final : public FramePass {
public:
    explicit CasterCullingPass(const FrameState& state) : state_(state) {}
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
};

} // namespace penumbra::render
