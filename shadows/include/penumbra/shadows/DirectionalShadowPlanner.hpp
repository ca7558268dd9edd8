#pragma once

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/DepthFit.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/CascadeData.hpp"
#include "penumbra/shadows/CascadeSplits.hpp"
#include "penumbra/shadows/CasterCulling.hpp"
#include "penumbra/shadows/DirectionalCascadeFit.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/LightSpaceCache.hpp"
#include "penumbra/shadows/NormalOffset.hpp"
#include "penumbra/shadows/ShadowAtlasLayout.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace penumbra::shadows {

// One directional light as the planner needs it: direction, strength, biases, filter, source size.
struct DirectionalShadowLightInput {
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // from the light into the scene
    float strength = 1.0f; // 0 turns the light's shadows off
    float nearPlaneOffset = LightShadowDefaults::nearPlaneOffset; // world units the near plane moves back (pancaking)
    float normalBias = LightShadowDefaults::normalBias; // multiple of the cascade's normal bias
    float slopeScaleBias = LightShadowDefaults::slopeScaleBias; // rasterizer slope-scaled depth bias of the shadow pass
    bool castsShadows = true;
    std::optional<ShadowFilter> filter; // nullopt: the atlas's (DirectionalShadowSettings::filter)
    float angularDiameter = LightShadowDefaults::angularDiameter; // degrees: the source size of soft filters
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    std::optional<StaticShadowUpdate> staticUpdate; // nullopt: the settings' (StaticShadowSettings::update)
};

// One cascade of one light: its fit, its atlas tile, matrix and viewport, its casters.
struct DirectionalCascadePlan {
    DirectionalShadowCascade fit;
    std::uint32_t tile = 0;
    glm::mat4 worldToAtlas{1.0f};
    rhi::Viewport viewport;
    // The casters drawn into the tile; left empty where they are culled on the GPU (culledOnGpu), which tests them
    // against `volume`.
    CasterCullingResult casters;
    CasterVolume volume; // the tile's light box and culling bias, the rules `casters` were culled by
};

// A directional light that got shadow tiles, with everything resolved from its input and the settings.
struct ShadowedDirectionalLight {
    std::uint32_t lightIndex = 0; // into the planner's input lights
    float strength = 1.0f;
    float normalBias = 1.0f;
    float slopeScaleBias = 0.0f;
    float depthBias = 0.0f; // the constant one, DirectionalShadowSettings::depthBias
    float nearPlaneOffset = 0.0f;
    ShadowFilter filter = ShadowFilter::PCF2x2; // the light's, resolved
    float angularDiameter = 0.0f;
    std::uint32_t firstTile = 0;
    std::vector<DirectionalCascadePlan> cascades;
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // into the scene
};

// Why a light (or, without a light index, the whole plan) gets no shadow tiles.
struct ShadowPlanNote {
    std::optional<std::uint32_t> lightIndex;
    std::string reason;
};

// The directional shadows of a frame: atlas layout, cascades, lights, notes and the lit shader's uniforms.
struct DirectionalShadowPlan {
    ShadowAtlasLayout atlas{256, 0};
    CascadeSplits splits;
    std::vector<Sphere> cullingSpheres; // per cascade, shared by every light
    std::vector<CascadeData> cascadeData; // per cascade, shared by every light
    std::vector<ShadowedDirectionalLight> lights; // at most 4: the shadow slots
    std::vector<int> shadowSlots; // per input light: its slot in `lights`, or -1
    std::vector<ShadowPlanNote> report;
    DirectionalShadowUniforms uniforms;
    // CascadeProjection::DepthFit over a histogram: the partition and half sizes the next frame's plan keeps.
    std::optional<DepthFitKept> depthFit;
};

// What CascadeProjection::DepthFit plans with: the last frame's histogram of the visible depths and what the last
// depth-fit plan kept (its DirectionalShadowPlan::depthFit); either may be missing.
struct DepthFitInput {
    const DepthHistogram* histogram = nullptr;
    const DepthFitKept* kept = nullptr;
};

// Where the planner takes the casters' light-space boxes from: a cache kept by the caller, with the change log of its
// caster list, or (no cache) boxes made anew.
struct LightSpaceInput {
    LightSpaceCache* cache = nullptr;
    const CasterChanges* changes = nullptr;
};

// The caster pass's normal offset for cascade `cascade` of `light`: the lit pass's reach there (the cascade's
// filter-sized texel diagonal times the light's normalBias) on the caster side, none on the receiver side.
CasterNormalOffset casterNormalOffset(const DirectionalShadowPlan& plan, const ShadowedDirectionalLight& light,
                                      std::uint32_t cascade);

// Plans a frame's directional shadows: the first 4 lights that cast shadows with strength > 0 and have a caster in
// their cascades' reach (castersInReach) get cascadeCount tiles each; every other light is listed in the report with
// the reason (never an exception). CascadeProjection::DepthFit is the close fit (view-depth bands) with its splits from
// the histogram's partition (depthFitPartition) and each light's tile around the footprint of the samples in its band
// (depthHistogramFootprint), the half sizes on a grid with hysteresis (depthFitHalfSize); where the histogram has
// occupancy grids for every light, every tile but the last is placed over them instead (depthFitTiles) and the last
// is fitted around every sample. Without a histogram (no frame reduced yet) it is the close fit over the usual
// splits, tile sizes on the grid. Throws rhi::Error only for settings that fail validate().
DirectionalShadowPlan planDirectionalShadows(const ShadowSettings& settings, const rhi::Conventions& conventions,
                                             const ShadowCamera& camera,
                                             std::span<const DirectionalShadowLightInput> lights,
                                             std::span<const Bounds> casterBounds, DepthFitInput depthFit = {},
                                             LightSpaceInput lightSpace = {});

} // namespace penumbra::shadows
