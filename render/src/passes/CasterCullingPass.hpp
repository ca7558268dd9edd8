#pragma once

#include "FrameState.hpp"

#include "penumbra/render/FramePass.hpp"
#include "penumbra/render/GpuScene.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/GpuCasterCulling.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"

namespace penumbra::render {

// ShadowSettings::culling gpu: every caster tested against every realtime atlas tile's volume (the directional
// cascades, then the local atlas tiles) in one dispatch, whose instance lists and indirect draws the atlas passes draw
// (FrameState::culling). The planner leaves those tiles' lists empty; cube-map faces stay culled by the planner.
class CasterCullingPass final : public FramePass {
public:
    CasterCullingPass(const FrameState& state, const GpuScene& scene, const shadows::DirectionalShadowPlan& plan,
                      const shadows::LocalShadowPlan& localPlan)
        : state_(state), scene_(scene), plan_(plan), localPlan_(localPlan)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    const GpuScene& scene_;
    const shadows::DirectionalShadowPlan& plan_;
    const shadows::LocalShadowPlan& localPlan_;
};

} // namespace penumbra::render
