#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include "penumbra/shadows/AtlasMatrix.hpp"
#include "penumbra/shadows/CasterBvh.hpp"
#include "penumbra/shadows/DirectionalCascadeFit.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/DirectionalSoftData.hpp"
#include "penumbra/shadows/LightBasis.hpp"
#include "penumbra/shadows/LocalLightProjection.hpp"
#include "penumbra/shadows/NormalOffset.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>

namespace penumbra::shadows {
namespace {

// The sphere around the union of the static casters' boxes.
Sphere boundingSphere(const StaticCasters& casters)
{
    Bounds box = casters.bounds[casters.indices.front()];
    for (const std::uint32_t i : casters.indices) {
        box.min = glm::min(box.min, casters.bounds[i].min);
        box.max = glm::max(box.max, casters.bounds[i].max);
    }
    return {0.5f * (box.min + box.max), std::max(0.5f * glm::length(box.max - box.min), 1e-3f)};
}

// The static casters' boxes, in the order of their indices.
std::vector<Bounds> staticBoundsOf(const StaticCasters& casters)
{
    std::vector<Bounds> bounds;
    bounds.reserve(casters.indices.size());
    for (const std::uint32_t i : casters.indices)
        bounds.push_back(casters.bounds[i]);
    return bounds;
}

// The static casters whose boxes meet a perspective view's frustum, as caster indices (ascending, as `staticBvh`'s
// entries follow the ascending indices): cullCastersInFrustum's list, walked down the hierarchy over the static boxes.
std::vector<std::uint32_t> castersInFrustum(const glm::mat4& view, float fov, float nearPlane, float farPlane,
                                            const CasterBvh& staticBvh, const StaticCasters& casters)
{
    std::vector<std::uint32_t> inside = staticBvh.inFrustum(frustumVolume(view, fov, nearPlane, farPlane));
    for (std::uint32_t& i : inside)
        i = casters.indices[i];
    return inside;
}

void planDirectional(StaticShadowPlan& plan, const ShadowSettings& settings, const rhi::Conventions& conventions,
                     std::span<const DirectionalShadowLightInput> lights, const StaticCasters& casters)
{
    std::vector<std::uint32_t> selected;
    for (std::uint32_t i = 0; i < lights.size(); ++i) {
        if (!lights[i].castsShadows || !(lights[i].strength > 0.0f) ||
            staticUpdateOf(lights[i].staticUpdate, settings) == StaticShadowUpdate::EveryFrame)
            continue;
        if (selected.size() == maxStaticDirectionalMaps) {
            plan.report.push_back(
                {LightKind::Directional, i,
                 fmt::format("no static map: all {} static directional maps are taken", maxStaticDirectionalMaps)});
            continue;
        }
        selected.push_back(i);
    }
    plan.directionalAtlas =
        ShadowAtlasLayout(settings.staticMaps.directionalAtlasSize, static_cast<std::uint32_t>(selected.size()));
    if (selected.empty())
        return;
    const Sphere sphere = boundingSphere(casters);
    const std::vector<std::uint32_t> all(casters.indices.begin(), casters.indices.end());
    const std::vector<Bounds> staticBounds = staticBoundsOf(casters);
    for (std::uint32_t tile = 0; tile < selected.size(); ++tile) {
        const std::uint32_t index = selected[tile];
        const DirectionalShadowLightInput& light = lights[index];
        const ShadowFilter filter = light.filter.value_or(settings.directional.filter);
        const LightSpaceCasters lightSpace = lightSpaceCasters(lightBasis(light.direction), staticBounds);
        const DirectionalShadowCascade fit = fitDirectionalCascade(sphere, lightSpace, plan.directionalAtlas.tileSize(),
                                                                   light.nearPlaneOffset, conventions);
        // The realtime cascades' normal offset: the filter-sized texel diagonal times the light's normal bias.
        const float reach = normalOffsetReach(light.normalBias, fit.texelSize, filter);
        const bool casterSide = light.normalBiasSide == NormalBiasSide::Caster;
        ShadowViewDraw view{.viewProjection = fit.viewProjection,
                            .slopeScaleBias = light.slopeScaleBias,
                            .depthBias = settings.directional.depthBias,
                            .pancake = true,
                            .ditherOrigin = ditherOrigin(fit, plan.directionalAtlas, tile)};
        if (casterSide)
            view.normalOffset = {reach, glm::vec4(glm::normalize(light.direction), 0.0f)};
        plan.uniforms.directionalWorldToMap[tile] =
            worldToAtlas(fit.viewProjection, tile, plan.directionalAtlas, conventions);
        plan.uniforms.directionalBounds[tile] = plan.directionalAtlas.tileTexelBounds(tile);
        plan.uniforms.directionalSoft[tile] =
            directionalTileSoft(fit, plan.uniforms.directionalWorldToMap[tile], lightSpace, conventions);
        plan.uniforms.directionalSource[tile] = {.tanHalfAngle = tanHalfAngularDiameter(light.angularDiameter),
                                                 .texelWorldSize = fit.texelSize};
        if (index < maxStaticMapDirectionalLights)
            plan.uniforms.directionalLights[index] = {.tile = static_cast<std::int32_t>(tile),
                                                      .strength = light.strength,
                                                      .normalOffset = casterSide ? 0.0f : reach,
                                                      .shadowFilter = filter};
        const ShadowFrustum frustum{fit.view, false, fit.halfSize, 0.0f, fit.farDepth - fit.nearDepth};
        plan.maps.push_back({LightKind::Directional,
                             index,
                             {{{tile, plan.directionalAtlas.viewport(tile), view, all}, fit.projection, frustum}},
                             fit.texelSize,
                             staticUpdateOf(light.staticUpdate, settings),
                             index});
    }
}

// What a spot or point light's static map needs of it.
struct LocalLightInput {
    LightKind kind;
    std::uint32_t index;
    glm::vec3 position;
    glm::vec3 direction; // spot lights
    float range;
    float outerAngle; // spot lights
    float strength;
    float normalBias;
    float slopeScaleBias;
    float nearPlane;
    std::optional<ShadowFilter> filter;
    NormalBiasSide normalBiasSide;
    std::optional<StaticShadowUpdate> staticUpdate;
    float sourceRadius; // soft filters
};

std::vector<LocalLightInput> localInputs(std::span<const SpotShadowInput> spots,
                                         std::span<const PointShadowInput> points)
{
    std::vector<LocalLightInput> inputs;
    for (std::uint32_t i = 0; i < spots.size(); ++i) {
        const SpotShadowInput& s = spots[i];
        inputs.push_back({LightKind::Spot, i, s.position, s.direction, s.range, s.outerAngle, s.strength, s.normalBias,
                          s.slopeScaleBias, s.nearPlane, s.filter, s.normalBiasSide, s.staticUpdate, s.sourceRadius});
    }
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const PointShadowInput& p = points[i];
        inputs.push_back({LightKind::Point, i, p.position, glm::vec3(0.0f, -1.0f, 0.0f), p.range, 0.0f, p.strength,
                          p.normalBias, p.slopeScaleBias, p.nearPlane, p.filter, p.normalBiasSide, p.staticUpdate,
                          p.sourceRadius});
    }
    return inputs;
}

// The light's views: a spot light's cone, or a point light's six faces (widened as the realtime tiles are).
struct LocalViews {
    float fov;
    std::vector<glm::mat4> views;
};

LocalViews localViews(const LocalLightInput& light, std::uint32_t tileSize, ShadowFilter filter, Toggle spotFovBias)
{
    if (light.kind == LightKind::Spot)
        return {spotFieldOfView(light.outerAngle, tileSize, filter, light.normalBias, spotFovBias),
                {spotView(light.position, light.direction)}};
    LocalViews faces{pointFaceFieldOfView(tileSize, filter, light.normalBias), {}};
    for (std::uint32_t face = 0; face < cubeFaceCount; ++face)
        faces.views.push_back(pointFaceView(static_cast<CubeFace>(face), light.position));
    return faces;
}

void planLocal(StaticShadowPlan& plan, const ShadowSettings& settings, const rhi::Conventions& conventions,
               std::span<const SpotShadowInput> spots, std::span<const PointShadowInput> points,
               const StaticCasters& casters)
{
    const std::vector<LocalLightInput> inputs = localInputs(spots, points);
    // Lights that shadow a static caster, and whether they fit: tiles are counted before the layout is known, and
    // the casters a view meets do not depend on the tile size, only the point faces' widening does (by a texel).
    std::vector<const LocalLightInput*> selected;
    std::uint32_t tiles = 0;
    for (const LocalLightInput& light : inputs) {
        if (!(light.strength > 0.0f) || staticUpdateOf(light.staticUpdate, settings) == StaticShadowUpdate::EveryFrame)
            continue;
        const std::uint32_t needed = light.kind == LightKind::Spot ? 1 : cubeFaceCount;
        if (tiles + needed > maxStaticLocalTiles) {
            plan.report.push_back({light.kind, light.index,
                                   fmt::format("no static map: needs {} of the static local atlas's {} tiles, {} "
                                               "are left",
                                               needed, maxStaticLocalTiles, maxStaticLocalTiles - tiles)});
            continue;
        }
        selected.push_back(&light);
        tiles += needed;
    }
    plan.localAtlas = ShadowAtlasLayout(settings.staticMaps.localAtlasSize, tiles);
    if (selected.empty())
        return;
    // One hierarchy for every view: each view's culling costs what it sees, not every static caster.
    const std::vector<Bounds> staticBounds = staticBoundsOf(casters);
    const CasterBvh staticBvh(staticBounds);
    std::uint32_t tile = 0;
    for (const LocalLightInput* light : selected) {
        const std::uint32_t tileSize = plan.localAtlas.tileSize();
        const ShadowFilter filter = light->filter.value_or(settings.local.filter);
        const LocalViews views = localViews(*light, tileSize, filter, settings.local.spotFovBias);
        const float nearPlane = localShadowNearPlane(light->range, light->nearPlane, settings.local);
        const glm::mat4 projection = conventions.perspective(views.fov, 1.0f, nearPlane, light->range);
        const float bias = localNormalBiasScale(projection, tileSize, filter, light->normalBias);
        const bool casterSide = light->normalBiasSide == NormalBiasSide::Caster;
        const std::uint32_t litIndex = light->index + (light->kind == LightKind::Point ? spots.size() : 0);
        plan.localLightMaps[litIndex] = {.tile = static_cast<std::int32_t>(tile), .strength = light->strength};
        StaticShadowMap map{light->kind, light->index, {}, 0.0f, staticUpdateOf(light->staticUpdate, settings),
                            litIndex};
        for (const glm::mat4& view : views.views) {
            // The dither follows the tile's own texel grid, as in the realtime atlas.
            ShadowViewDraw draw{.viewProjection = projection * view,
                                .slopeScaleBias = light->slopeScaleBias,
                                .depthBias = settings.local.depthBias,
                                .ditherOrigin = -glm::vec2(plan.localAtlas.tileOffset(tile))};
            if (casterSide)
                draw.normalOffset = {bias, glm::vec4(light->position, 1.0f)};
            plan.uniforms.localWorldToMap[tile] = worldToAtlas(draw.viewProjection, tile, plan.localAtlas, conventions);
            plan.uniforms.localBounds[tile] = plan.localAtlas.tileTexelBounds(tile);
            plan.uniforms.localTiles[tile] = {.normalBias = casterSide ? 0.0f : bias, .shadowFilter = filter};
            plan.uniforms.localSoft[tile] =
                perspectiveTileSoft(projection, tileSize, light->sourceRadius, nearPlane, conventions);
            map.tiles.push_back({{tile, plan.localAtlas.viewport(tile), draw,
                                  castersInFrustum(view, views.fov, nearPlane, light->range, staticBvh, casters)},
                                 projection,
                                 ShadowFrustum{view, true, views.fov, nearPlane, light->range}});
            ++tile;
        }
        plan.maps.push_back(std::move(map));
    }
}

// Window depth of view-space z (negative in front): (t22 z + t32) / (t23 z + t33) with t = clipToTexture * projection.
glm::mat2 depthRows(const glm::mat4& projection, const rhi::Conventions& conventions)
{
    const glm::mat4 t = conventions.clipToTexture() * projection;
    return {t[2][2], t[2][3], t[3][2], t[3][3]};
}

} // namespace

float linearShadowDepth(float windowDepth, const glm::mat4& projection, const rhi::Conventions& conventions)
{
    const glm::mat2 r = depthRows(projection, conventions);
    // d (t23 z + t33) = t22 z + t32, solved for z; the depth along -z is its negation.
    return -(r[1][0] - windowDepth * r[1][1]) / (windowDepth * r[0][1] - r[0][0]);
}

float windowShadowDepth(float linearDepth, const glm::mat4& projection, const rhi::Conventions& conventions)
{
    const glm::mat2 r = depthRows(projection, conventions);
    const float z = -linearDepth;
    return (r[0][0] * z + r[1][0]) / (r[0][1] * z + r[1][1]);
}

StaticShadowPlan planStaticShadows(const ShadowSettings& settings, const rhi::Conventions& conventions,
                                   std::span<const DirectionalShadowLightInput> lights,
                                   std::span<const SpotShadowInput> spots, std::span<const PointShadowInput> points,
                                   const StaticCasters& casters)
{
    validate(settings);
    StaticShadowPlan plan;
    plan.localLightMaps.assign(spots.size() + points.size(), StaticLocalLightMap{});
    if (casters.indices.empty())
        return plan;
    planDirectional(plan, settings, conventions, lights, casters);
    planLocal(plan, settings, conventions, spots, points, casters);
    plan.uniforms.directionalAtlasSize = static_cast<float>(plan.directionalAtlas.atlasSize());
    plan.uniforms.localAtlasSize = static_cast<float>(plan.localAtlas.atlasSize());
    return plan;
}

} // namespace penumbra::shadows
