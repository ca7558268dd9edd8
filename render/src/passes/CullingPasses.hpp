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

// ShadowSettings::culling gpu: a culling's dispatches (FrameState::culling or viewCulling), whose instance lists and
// indirect draws later passes draw. Casters: every caster tested against every tile's volume, whose lists
// (kCulledCasters) the atlas passes draw; the planner leaves those tiles' lists empty, and cube-map faces stay culled
// by the planner. View (with instancing): the opaque lit objects against the camera's view (GpuViewCulling), whose
// lists (kViewCulled) the prepasses and the lit passes draw.
class CullingPass final : public FramePass {
public:
    enum class Kind { Casters, View };
    CullingPass(const FrameState& state, Kind kind) : state_(state), kind_(kind) {}
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    shadows::GpuCasterCulling* culling() const;

    const FrameState& state_;
    Kind kind_;
};

} // namespace penumbra::render
