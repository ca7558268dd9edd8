#include "penumbra/shadows/DirectionalShadowPlanner.hpp"

#include "penumbra/shadows/AtlasMatrix.hpp"
#include "penumbra/shadows/DirectionalSoftData.hpp"
#include "penumbra/shadows/FrustumSliceSphere.hpp"
#include "penumbra/shadows/ShadowFade.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::shadows {
namespace {

// The reason a light gets no shadows, or nothing when it may get a slot.
std::optional<std::string> exclusion(const DirectionalShadowLightInput& light, std::size_t slotsTaken)
{
    if (!light.castsShadows)
        return "casts no shadows";
    if (!(light.strength > 0.0f))
        return fmt::format("shadow strength is {}", light.strength);
    const float length = glm::length(light.direction);
    if (!(length > 0.0f) || !std::isfinite(length))
        return "direction is zero or not finite";
    if (slotsTaken == maxShadowedDirectionalLights)
        return fmt::format("beyond the limit of {} shadowed directional lights", maxShadowedDirectionalLights);
    return std::nullopt;
}

// The soft shadows' blocks but for the tiles' (directionalTileSoft).
void fillSoftUniforms(DirectionalShadowPlan& plan, const ShadowSettings& settings)
{
    DirectionalShadowUniforms& u = plan.uniforms;
    u.soft = softShadowUniforms(settings.soft);
    const float atlasFactor = normalBiasFilterFactor(settings.directional.filter);
    for (std::size_t slot = 0; slot < plan.lights.size(); ++slot) {
        const ShadowedDirectionalLight& light = plan.lights[slot];
        u.lights[slot].tanHalfAngle = tanHalfAngularDiameter(light.angularDiameter);
        u.lights[slot].filterBiasScale = normalBiasFilterFactor(light.filter) / atlasFactor;
    }
}

void fillUniforms(DirectionalShadowPlan& plan, const ShadowSettings& settings)
{
    DirectionalShadowUniforms& u = plan.uniforms;
    u.atlasSize = static_cast<float>(plan.atlas.atlasSize());
    u.fade = shadowDistanceFade(settings);
    u.cascadeCount = static_cast<int>(plan.splits.count);
    u.defaultFilter = settings.directional.filter;
    u.cascadeBlend = settings.directional.cascadeBlend;
    u.shadowedLightCount = static_cast<int>(plan.lights.size());
    u.cascadeProjection = settings.directional.projection;
    std::copy(plan.cascadeData.begin(), plan.cascadeData.end(), u.cascades.begin());
    for (std::size_t slot = 0; slot < plan.lights.size(); ++slot) {
        const ShadowedDirectionalLight& light = plan.lights[slot];
        // On the caster side the lit pass looks up where the surface is.
        const float receiverBias = light.normalBiasSide == NormalBiasSide::Receiver ? light.normalBias : 0.0f;
        u.lights[slot].strength = light.strength;
        u.lights[slot].normalBias = receiverBias;
        u.lights[slot].firstTile = static_cast<std::int32_t>(light.firstTile);
        u.lights[slot].shadowFilter = light.filter;
        for (const DirectionalCascadePlan& cascade : light.cascades) {
            u.worldToAtlas[cascade.tile] = cascade.worldToAtlas;
            u.tileBounds[cascade.tile] = plan.atlas.tileTexelBounds(cascade.tile);
        }
    }
}

// The frustum slice each cascade is fitted to. Close fit with a soft or dithered blend: a slice starts where the
// previous cascade's fade band does, so that the blended receivers lie in both tiles.
std::vector<FrustumSlice> cascadeSlices(const ShadowCamera& camera, const CascadeSplits& splits,
                                        const DirectionalShadowSettings& directional)
{
    const bool overlap =
        directional.projection == CascadeProjection::Close && directional.cascadeBlend != CascadeBlend::Hard;
    std::vector<FrustumSlice> slices;
    for (std::uint32_t c = 0; c < splits.count; ++c) {
        const float nearDistance = overlap && c > 0
                                       ? std::max(camera.nearPlane, splits.nearOf(c) * (1.0f - directional.cascadeFade))
                                       : splits.nearOf(c);
        slices.push_back({camera, nearDistance, splits.farOf(c)});
    }
    return slices;
}

// Close fit: one tile half size per cascade, the largest any light's slice bounds need, so that every light's tile
// of a cascade has the texel size its CascadeData carries. The margin is the widest light's reach past its slice:
// its filter's normal bias factor in texels for the taps, sqrt 2 times that times its normal bias for the offset.
std::vector<float> closeFitHalfSizes(const std::vector<FrustumSlice>& slices,
                                     std::span<const ShadowedDirectionalLight> lights, std::uint32_t tileSize)
{
    float margin = 0.0f;
    for (const ShadowedDirectionalLight& light : lights) {
        const float receiverBias = light.normalBiasSide == NormalBiasSide::Receiver ? light.normalBias : 0.0f;
        margin = std::max(margin, normalBiasFilterFactor(light.filter) * (1.0f + std::sqrt(2.0f) * receiverBias));
    }
    std::vector<float> halfSizes;
    for (const FrustumSlice& slice : slices) {
        const std::array<glm::vec3, 8> corners =
            frustumSliceCorners(slice.camera, slice.nearDistance, slice.farDistance);
        float half = 0.0f;
        for (const ShadowedDirectionalLight& light : lights)
            half = std::max(half,
                            closeFitHalfSize(lightSpaceBounds(lightBasis(light.direction), corners), tileSize, margin));
        halfSizes.push_back(half);
    }
    return halfSizes;
}

} // namespace

CasterNormalOffset casterNormalOffset(const DirectionalShadowPlan& plan, const ShadowedDirectionalLight& light,
                                      std::uint32_t cascade)
{
    if (light.normalBiasSide != NormalBiasSide::Caster || cascade >= plan.cascadeData.size())
        return {};
    return {light.normalBias * plan.cascadeData[cascade].normalBias, glm::vec4(light.direction, 0.0f)};
}

DirectionalShadowPlan planDirectionalShadows(const ShadowSettings& settings, const rhi::Conventions& conventions,
                                             const ShadowCamera& camera,
                                             std::span<const DirectionalShadowLightInput> lights,
                                             std::span<const Bounds> casterBounds,
                                             std::optional<ViewDepthRange> visibleDepths)
{
    validate(settings);
    const DirectionalShadowSettings& directional = settings.directional;
    DirectionalShadowPlan plan;
    // Depth fit is the stable fit (spheres snapped to texels) over the visible depths' splits.
    plan.splits = directional.projection == CascadeProjection::DepthFit && visibleDepths
                      ? depthFitSplits(*visibleDepths, camera.nearPlane, camera.farPlane, settings.maxDistance,
                                       directional.cascadeCount, directional.cascadeRatios, directional.depthFitSteps)
                      : cascadeSplits(camera.nearPlane, camera.farPlane, settings.maxDistance, directional.cascadeCount,
                                      directional.cascadeRatios);
    plan.shadowSlots.assign(lights.size(), -1);
    const bool distanceReachesPastNear = plan.splits.farOf(plan.splits.count - 1) > camera.nearPlane;
    if (!distanceReachesPastNear)
        plan.report.push_back({std::nullopt, fmt::format("the shadow distance {} does not reach past the camera's "
                                                         "near plane {}",
                                                         settings.maxDistance, camera.nearPlane)});

    const std::vector<FrustumSlice> slices = cascadeSlices(camera, plan.splits, directional);
    std::vector<Sphere> cullingSpheres;
    for (const FrustumSlice& slice : slices)
        cullingSpheres.push_back(frustumSliceSphere(camera, slice.nearDistance, slice.farDistance));
    std::vector<std::uint32_t> selected;
    std::vector<LightSpaceCasters> selectedCasters;
    for (std::uint32_t i = 0; i < lights.size(); ++i) {
        std::optional<std::string> reason = exclusion(lights[i], selected.size());
        if (!reason && !distanceReachesPastNear)
            reason = "no shadow distance in front of the camera";
        std::optional<LightSpaceCasters> casters;
        if (!reason) {
            casters = lightSpaceCasters(lightBasis(lights[i].direction), casterBounds);
            if (!castersInReach(*casters, cullingSpheres))
                reason = "no caster in its cascades' reach";
        }
        if (reason) {
            plan.report.push_back({i, std::move(*reason)});
            continue;
        }
        plan.shadowSlots[i] = static_cast<int>(selected.size());
        selected.push_back(i);
        selectedCasters.push_back(std::move(*casters));
    }

    const std::uint32_t cascadeCount = directional.cascadeCount;
    const bool close = directional.projection == CascadeProjection::Close;
    plan.atlas = ShadowAtlasLayout(directional.atlasSize, static_cast<std::uint32_t>(selected.size()) * cascadeCount);
    if (!selected.empty())
        plan.cullingSpheres = cullingSpheres;
    for (std::uint32_t slot = 0; slot < selected.size(); ++slot) {
        const DirectionalShadowLightInput& input = lights[selected[slot]];
        plan.lights.push_back({selected[slot],
                               input.strength,
                               input.normalBias,
                               input.slopeScaleBias,
                               input.nearPlaneOffset,
                               input.filter.value_or(directional.filter),
                               input.angularDiameter,
                               directionalTileIndex(slot, 0, cascadeCount),
                               {},
                               input.normalBiasSide,
                               input.direction});
    }
    const std::vector<float> halfSizes =
        close ? closeFitHalfSizes(slices, plan.lights, plan.atlas.tileSize()) : std::vector<float>();
    const float cullingFactor = cascadeBlendCullingFactor(directional.cascadeFade);
    const bool gpuCulling = culledOnGpu(settings);
    for (std::uint32_t slot = 0; slot < plan.lights.size(); ++slot) {
        ShadowedDirectionalLight& light = plan.lights[slot];
        const LightSpaceCasters& casters = selectedCasters[slot];
        for (std::uint32_t c = 0; c < cascadeCount; ++c) {
            DirectionalCascadePlan cascade;
            const FrustumSlice& slice = slices[c];
            cascade.fit =
                close ? fitCloseCascade(lightSpaceBounds(casters.basis, frustumSliceCorners(camera, slice.nearDistance,
                                                                                            slice.farDistance)),
                                        halfSizes[c], plan.cullingSpheres[c], casters, plan.atlas.tileSize(),
                                        light.nearPlaneOffset, conventions)
                      : fitDirectionalCascade(plan.cullingSpheres[c], casters, plan.atlas.tileSize(),
                                              light.nearPlaneOffset, conventions);
            cascade.tile = directionalTileIndex(slot, c, cascadeCount);
            cascade.worldToAtlas = worldToAtlas(cascade.fit.viewProjection, cascade.tile, plan.atlas, conventions);
            cascade.viewport = plan.atlas.viewport(cascade.tile);
            const std::optional<Sphere> previousSphere =
                c > 0 ? std::optional<Sphere>(plan.cullingSpheres[c - 1]) : std::nullopt;
            const std::optional<FrustumSlice> previousSlice =
                c > 0 ? std::optional<FrustumSlice>(slices[c - 1]) : std::nullopt;
            cascade.volume = close ? closeCascadeVolume(cascade.fit, previousSlice, cullingFactor)
                                   : cascadeVolume(cascade.fit, previousSphere, cullingFactor);
            // Culled on the GPU, the tile lists none here: the culling pass tests every caster against the volume.
            if (!gpuCulling)
                cascade.casters = close ? cullCloseFitShadowCasters(cascade.fit, casters, previousSlice, cullingFactor)
                                        : cullShadowCasters(cascade.fit, casters, previousSphere, cullingFactor);
            plan.uniforms.tileSoft[cascade.tile] =
                directionalTileSoft(cascade.fit, cascade.worldToAtlas, casters, conventions);
            light.cascades.push_back(std::move(cascade));
        }
    }
    // The texel size depends on the slice and the tile size only (close fit: the planner gives every light's tile of
    // a cascade the same half size), so any light's serves.
    if (!plan.lights.empty())
        for (std::uint32_t c = 0; c < cascadeCount; ++c)
            plan.cascadeData.push_back(cascadeData(plan.cullingSpheres[c], plan.lights[0].cascades[c].fit.texelSize,
                                                   directional.filter, plan.splits.farOf(c)));
    fillUniforms(plan, settings);
    fillSoftUniforms(plan, settings);
    return plan;
}

} // namespace penumbra::shadows
