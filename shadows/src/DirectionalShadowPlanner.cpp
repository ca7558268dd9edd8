#include "penumbra/shadows/DirectionalShadowPlanner.hpp"

#include "penumbra/shadows/AtlasMatrix.hpp"
#include "penumbra/shadows/DepthFitTiles.hpp"
#include "penumbra/shadows/DirectionalSoftData.hpp"
#include "penumbra/shadows/FrustumSliceSphere.hpp"
#include "penumbra/shadows/ShadowFade.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <algorithm>
#include <deque>
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

// The frustum slice each cascade is fitted to. Close and depth fit with a soft or dithered blend: a slice starts where
// the previous cascade's fade band does, so that the blended receivers lie in both tiles.
std::vector<FrustumSlice> cascadeSlices(const ShadowCamera& camera, const CascadeSplits& splits,
                                        const DirectionalShadowSettings& directional)
{
    const bool overlap =
        directional.projection != CascadeProjection::Stable && directional.cascadeBlend != CascadeBlend::Hard;
    std::vector<FrustumSlice> slices;
    for (std::uint32_t c = 0; c < splits.count; ++c) {
        const float nearDistance = overlap && c > 0
                                       ? std::max(camera.nearPlane, splits.nearOf(c) * (1.0f - directional.cascadeFade))
                                       : splits.nearOf(c);
        slices.push_back({camera, nearDistance, splits.farOf(c)});
    }
    return slices;
}

// Close and depth fit: the light-space bounds each light's tile of each cascade is fitted around, [slot][cascade];
// `mapped` (depth fit's map-based selection) gives every tile the whole view's depth range.
// Close fit: the slice's. Depth fit over a histogram that measured the light: x and y of the footprint of the samples
// in the cascade's bins (from the bin of the slice's near distance, which a blend's overlap moves nearer), z the
// slice's; the slice's where the bins hold none of the light's samples.
// `lastHoldsAll` (tiles placed over the occupancy grids): the last cascade's footprint is every bin's.
std::vector<std::vector<Bounds>> fittedBounds(const std::vector<FrustumSlice>& slices,
                                              std::span<const ShadowedDirectionalLight> lights,
                                              const DepthHistogram* histogram, std::span<const std::uint32_t> edges,
                                              bool mapped, bool lastHoldsAll)
{
    std::vector<std::vector<Bounds>> bounds(lights.size());
    for (std::size_t slot = 0; slot < lights.size(); ++slot) {
        const LightBasis basis = lightBasis(lights[slot].direction);
        std::optional<std::uint32_t> measured;
        if (histogram)
            for (std::uint32_t s = 0; s < histogram->lightDirections.size(); ++s)
                if (histogram->lightDirections[s] == lights[slot].direction)
                    measured = s;
        // Map-based selection (CascadeSelection.hpp) gives a tile every receiver its square holds, at any view depth:
        // its depth planes hold the whole view's.
        const Bounds view =
            lightSpaceBounds(basis, frustumSliceCorners(slices.front().camera, slices.front().nearDistance,
                                                        slices.back().farDistance));
        for (std::size_t c = 0; c < slices.size(); ++c) {
            const FrustumSlice& slice = slices[c];
            Bounds b =
                lightSpaceBounds(basis, frustumSliceCorners(slice.camera, slice.nearDistance, slice.farDistance));
            if (mapped) {
                b.min.z = view.min.z;
                b.max.z = view.max.z;
            }
            if (measured && c + 1 < edges.size()) {
                const std::uint32_t first =
                    lastHoldsAll && c + 1 == slices.size()
                        ? edges.front()
                        : std::min(edges[c], depthHistogramBin(histogram->firstOctave, slice.nearDistance));
                if (const std::optional<Bounds> footprint =
                        depthHistogramFootprint(*histogram, *measured, first, edges[c + 1])) {
                    b.min = glm::vec3(glm::vec2(footprint->min), b.min.z);
                    b.max = glm::vec3(glm::vec2(footprint->max), b.max.z);
                }
            }
            bounds[slot].push_back(b);
        }
    }
    return bounds;
}

// One tile half size per cascade, the largest any light's bounds need, so that every light's tile of a cascade has
// the texel size its CascadeData carries; depth fit puts it on its grid, against the kept one. The margin is the
// widest light's reach past its bounds: its filter's normal bias factor in texels for the taps, sqrt 2 times that
// times its normal bias for the offset.
float fitMargin(std::span<const ShadowedDirectionalLight> lights)
{
    float margin = 0.0f;
    for (const ShadowedDirectionalLight& light : lights) {
        const float receiverBias = light.normalBiasSide == NormalBiasSide::Receiver ? light.normalBias : 0.0f;
        margin = std::max(margin, normalBiasFilterFactor(light.filter) * (1.0f + std::sqrt(2.0f) * receiverBias));
    }
    return margin;
}

std::vector<float> fittedHalfSizes(const std::vector<std::vector<Bounds>>& bounds,
                                   std::span<const ShadowedDirectionalLight> lights, std::uint32_t tileSize,
                                   std::size_t cascadeCount, const DirectionalShadowSettings& directional,
                                   const DepthFitKept* kept)
{
    const float margin = fitMargin(lights);
    std::vector<float> halfSizes;
    for (std::size_t c = 0; c < cascadeCount; ++c) {
        float half = 0.0f;
        for (const std::vector<Bounds>& lightBounds : bounds)
            half = std::max(half, closeFitHalfSize(lightBounds[c], tileSize, margin));
        if (directional.projection == CascadeProjection::DepthFit)
            half = depthFitHalfSize(half,
                                    kept && kept->halfSizes.size() == cascadeCount
                                        ? std::optional<float>(kept->halfSizes[c])
                                        : std::nullopt,
                                    directional.depthFitSteps, directional.depthFitHysteresis, c + 1 < cascadeCount);
        halfSizes.push_back(half);
    }
    return halfSizes;
}

// The histogram slot that measured each plan light; nullopt unless every light has one with occupancy grids.
std::optional<std::vector<std::uint32_t>> occupancySlots(const DepthHistogram* histogram,
                                                         std::span<const ShadowedDirectionalLight> lights)
{
    if (!histogram || histogram->occupancy.size() != histogram->lightDirections.size() || lights.empty())
        return std::nullopt;
    std::vector<std::uint32_t> slots;
    for (const ShadowedDirectionalLight& light : lights) {
        const auto at =
            std::find(histogram->lightDirections.begin(), histogram->lightDirections.end(), light.direction);
        if (at == histogram->lightDirections.end() ||
            histogram->occupancy[at - histogram->lightDirections.begin()].empty())
            return std::nullopt;
        slots.push_back(static_cast<std::uint32_t>(at - histogram->lightDirections.begin()));
    }
    return slots;
}

// Depth fit over occupancy grids: every tile but the last placed by depthFitTiles, each light's square about its
// slot's centre (its depth planes the view's, as fittedBounds gives them); the last keeps fittedBounds' footprint of
// every sample. Sets `kept`'s centres.
void placeOverOccupancy(std::vector<std::vector<Bounds>>& bounds, std::vector<float>& halfSizes,
                        const DepthHistogram& histogram, std::span<const std::uint32_t> slots,
                        std::span<const ShadowedDirectionalLight> lights, std::uint32_t tileSize,
                        const DirectionalShadowSettings& directional, const DepthFitKept* kept, DepthFitKept& keep)
{
    const std::size_t placed = halfSizes.size() - 1;
    // Map-based selection's inset (selectCascade): twice the filter's reach, with the snap's half texel, each side.
    const float servedShare = 1.0f - 2.0f * (2.0f * fitMargin(lights) + 1.0f) / static_cast<float>(tileSize);
    std::optional<DepthFitTiles> keptTiles;
    if (kept && kept->halfSizes.size() == halfSizes.size())
        keptTiles = DepthFitTiles{{kept->halfSizes.begin(), kept->halfSizes.end() - 1}, kept->centres};
    const DepthFitTiles tiles =
        depthFitTiles(histogram, {.placed = static_cast<std::uint32_t>(placed),
                                  .lastHalfSize = halfSizes.back(),
                                  .servedShare = servedShare,
                                  .stepsPerOctave = directional.depthFitSteps,
                                  .toleranceLog2 = directional.depthFitSteps > 0
                                                       ? directional.depthFitHysteresis /
                                                             static_cast<float>(directional.depthFitSteps)
                                                       : 0.0f,
                                  .kept = keptTiles ? &*keptTiles : nullptr});
    if (tiles.halfSizes.size() != placed)
        return;
    for (std::size_t c = 0; c < placed; ++c) {
        halfSizes[c] = tiles.halfSizes[c];
        for (std::size_t l = 0; l < lights.size(); ++l) {
            const glm::vec2 centre = tiles.centres[c][slots[l]];
            const glm::vec2 reach(servedShare * halfSizes[c]);
            bounds[l][c].min = glm::vec3(centre - reach, bounds[l][c].min.z);
            bounds[l][c].max = glm::vec3(centre + reach, bounds[l][c].max.z);
        }
    }
    keep.halfSizes = halfSizes;
    keep.centres = tiles.centres;
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
                                             std::span<const Bounds> casterBounds, DepthFitInput depthFit,
                                             LightSpaceInput lightSpace)
{
    validate(settings);
    const DirectionalShadowSettings& directional = settings.directional;
    DirectionalShadowPlan plan;
    // Depth fit: the close fit over the histogram's partition, each tile around its samples' footprint.
    std::vector<std::uint32_t> edges;
    if (directional.projection == CascadeProjection::DepthFit && depthFit.histogram) {
        const float tolerance = directional.depthFitSteps > 0
                                    ? directional.depthFitHysteresis / static_cast<float>(directional.depthFitSteps)
                                    : 0.0f;
        edges = depthFitPartition(*depthFit.histogram, directional.cascadeCount,
                                  static_cast<std::uint32_t>(depthFit.histogram->lightDirections.size()),
                                  depthFit.kept ? std::span<const std::uint32_t>(depthFit.kept->edges)
                                                : std::span<const std::uint32_t>(),
                                  tolerance);
    }
    plan.splits = !edges.empty() ? depthFitSplits(*depthFit.histogram, edges, camera.nearPlane, camera.farPlane,
                                                  settings.maxDistance)
                                 : cascadeSplits(camera.nearPlane, camera.farPlane, settings.maxDistance,
                                                 directional.cascadeCount, directional.cascadeRatios);
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
    // The selected lights' boxes: the cache's, or made here (a deque keeps them in place as it grows).
    std::deque<LightSpaceCasters> made;
    std::vector<const LightSpaceCasters*> selectedCasters;
    for (std::uint32_t i = 0; i < lights.size(); ++i) {
        std::optional<std::string> reason = exclusion(lights[i], selected.size());
        if (!reason && !distanceReachesPastNear)
            reason = "no shadow distance in front of the camera";
        const LightSpaceCasters* casters = nullptr;
        if (!reason) {
            casters = lightSpace.cache && lightSpace.changes
                          ? &lightSpace.cache->casters(lights[i].direction, casterBounds, *lightSpace.changes)
                          : &made.emplace_back(lightSpaceCasters(lightBasis(lights[i].direction), casterBounds));
            if (!castersInReach(*casters, cullingSpheres))
                reason = "no caster in its cascades' reach";
        }
        if (reason) {
            plan.report.push_back({i, std::move(*reason)});
            continue;
        }
        plan.shadowSlots[i] = static_cast<int>(selected.size());
        selected.push_back(i);
        selectedCasters.push_back(casters);
    }

    const std::uint32_t cascadeCount = directional.cascadeCount;
    // Depth fit fits its tiles as the close fit does, around bounds in light space.
    const bool close = directional.projection != CascadeProjection::Stable;
    plan.atlas = ShadowAtlasLayout(directional.atlasSize, static_cast<std::uint32_t>(selected.size()) * cascadeCount);
    if (!selected.empty())
        plan.cullingSpheres = cullingSpheres;
    for (std::uint32_t slot = 0; slot < selected.size(); ++slot) {
        const DirectionalShadowLightInput& input = lights[selected[slot]];
        plan.lights.push_back({selected[slot],
                               input.strength,
                               input.normalBias,
                               input.slopeScaleBias,
                               directional.depthBias,
                               input.nearPlaneOffset,
                               input.filter.value_or(directional.filter),
                               input.angularDiameter,
                               directionalTileIndex(slot, 0, cascadeCount),
                               {},
                               input.normalBiasSide,
                               input.direction});
    }
    const std::optional<std::vector<std::uint32_t>> occupancy =
        edges.empty() || cascadeCount < 2 ? std::nullopt : occupancySlots(depthFit.histogram, plan.lights);
    std::vector<std::vector<Bounds>> bounds =
        close ? fittedBounds(slices, plan.lights, edges.empty() ? nullptr : depthFit.histogram, edges,
                             directional.projection == CascadeProjection::DepthFit, occupancy.has_value())
              : std::vector<std::vector<Bounds>>();
    std::vector<float> halfSizes =
        close ? fittedHalfSizes(bounds, plan.lights, plan.atlas.tileSize(), cascadeCount, directional, depthFit.kept)
              : std::vector<float>();
    if (!edges.empty()) {
        plan.depthFit = DepthFitKept{edges, halfSizes, {}};
        if (occupancy)
            placeOverOccupancy(bounds, halfSizes, *depthFit.histogram, *occupancy, plan.lights, plan.atlas.tileSize(),
                               directional, depthFit.kept, *plan.depthFit);
    }
    const float cullingFactor = cascadeBlendCullingFactor(directional.cascadeFade);
    const bool gpuCulling = culledOnGpu(settings);
    for (std::uint32_t slot = 0; slot < plan.lights.size(); ++slot) {
        ShadowedDirectionalLight& light = plan.lights[slot];
        const LightSpaceCasters& casters = *selectedCasters[slot];
        for (std::uint32_t c = 0; c < cascadeCount; ++c) {
            DirectionalCascadePlan cascade;
            cascade.fit = close ? fitCloseCascade(bounds[slot][c], halfSizes[c], plan.cullingSpheres[c], casters,
                                                  plan.atlas.tileSize(), light.nearPlaneOffset, conventions)
                                : fitDirectionalCascade(plan.cullingSpheres[c], casters, plan.atlas.tileSize(),
                                                        light.nearPlaneOffset, conventions);
            cascade.tile = directionalTileIndex(slot, c, cascadeCount);
            cascade.worldToAtlas = worldToAtlas(cascade.fit.viewProjection, cascade.tile, plan.atlas, conventions);
            cascade.viewport = plan.atlas.viewport(cascade.tile);
            // Depth fit's tiles are chosen by what they hold, not by view depth: no caster is left to the one before.
            const bool banded = directional.projection == CascadeProjection::Close && c > 0;
            const std::optional<Sphere> previousSphere =
                c > 0 ? std::optional<Sphere>(plan.cullingSpheres[c - 1]) : std::nullopt;
            const std::optional<FrustumSlice> previousSlice =
                banded ? std::optional<FrustumSlice>(slices[c - 1]) : std::nullopt;
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
    // Depth fit's last band reaches the shadow distance, where the close fit's does: its far split is only the
    // farthest surface seen, and the band's fade must not fall on what is seen.
    const float shadowFar = std::max(std::min(settings.maxDistance, camera.farPlane), camera.nearPlane);
    if (!plan.lights.empty())
        for (std::uint32_t c = 0; c < cascadeCount; ++c)
            plan.cascadeData.push_back(
                cascadeData(plan.cullingSpheres[c], plan.lights[0].cascades[c].fit.texelSize, directional.filter,
                            !edges.empty() && c + 1 == cascadeCount ? std::max(shadowFar, plan.splits.farOf(c))
                                                                    : plan.splits.farOf(c)));
    fillUniforms(plan, settings);
    fillSoftUniforms(plan, settings);
    return plan;
}

} // namespace penumbra::shadows
