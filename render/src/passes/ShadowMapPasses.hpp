#pragma once

#include "FrameState.hpp"

#include "penumbra/render/FramePass.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/LocalShadowPass.hpp"

namespace penumbra::render {

class LocalTileCache;
class StaticShadowCache;
class StaticTileCache;

// The static maps StaticShadowCache::prepare chose this frame, drawn into the static atlases.
class StaticMapsPass final : public FramePass {
public:
    StaticMapsPass(const FrameState& state, StaticShadowCache& cache) : state_(state), cache_(cache) {}
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    StaticShadowCache& cache_;
};

// RealtimeCasters::Dynamic: the static casters' depth of the realtime tiles, copied from StaticTileCache into the
// directional or the local atlas, for the atlas pass to draw the dynamic casters over.
class StaticTilesPass final : public FramePass {
public:
    enum class Atlas : std::uint8_t { Directional, Local };
    StaticTilesPass(const FrameState& state, StaticTileCache& cache, Atlas atlas)
        : state_(state), cache_(cache), atlas_(atlas)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const std::vector<shadows::ShadowTileDraw>& tiles() const;

    const FrameState& state_;
    StaticTileCache& cache_;
    Atlas atlas_;
};

// The cascades' casters into the directional atlas.
class DirectionalAtlasPass final : public FramePass {
public:
    DirectionalAtlasPass(const FrameState& state, shadows::DirectionalShadowPass& pass,
                         const shadows::DirectionalShadowPlan& plan)
        : state_(state), pass_(pass), plan_(plan)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    shadows::DirectionalShadowPass& pass_;
    const shadows::DirectionalShadowPlan& plan_;
};

// Spot and point casters into the local atlas and the shadow cube maps.
class LocalAtlasPass final : public FramePass {
public:
    LocalAtlasPass(const FrameState& state, shadows::LocalShadowPass& pass, LocalTileCache& cache,
                   const shadows::LocalShadowPlan& plan, const scene::Scene& scene)
        : state_(state), pass_(pass), cache_(cache), plan_(plan), scene_(scene)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    shadows::LocalShadowPass& pass_;
    LocalTileCache& cache_;
    const shadows::LocalShadowPlan& plan_;
    const scene::Scene& scene_;
};

} // namespace penumbra::render
