#include "penumbra/shadows/DirectionalShadowPlanner.hpp"

#include "penumbra/shadows/AtlasMatrix.hpp"
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

// What a tile texel adds to become the light's own texel grid (whole texels: the fit snaps the tile's centre), per
// axis in the direction the atlas runs along the light's right and up axes.
glm::vec2 lightTexelAnchor(const DirectionalCascadePlan& cascade)
{
    const DirectionalShadowCascade& fit = cascade.fit;
    const glm::vec3 origin = fit.basis.right * fit.snappedCentre.x + fit.basis.up * fit.snappedCentre.y;
    const auto atlasX = [&](glm::vec3 p) { return (cascade.worldToAtlas * glm::vec4(p, 1.0f)).x; };
    const auto atlasY = [&](glm::vec3 p) { return (cascade.worldToAtlas * glm::vec4(p, 1.0f)).y; };
    const float signX = atlasX(origin + fit.basis.right) > atlasX(origin) ? 1.0f : -1.0f;
    const float signY = atlasY(origin + fit.basis.up) > atlasY(origin) ? 1.0f : -1.0f;
    return {std::round(signX * fit.snappedCentre.x / fit.texelSize), std::round(signY * fit.snappedCentre.y / fit.texelSize)};
}

// The light-space depth nearest the light of any caster: no blocker lies nearer. Unlike the near plane, which follows
// the cascade's sphere, it does not move with the camera, so neither does the blocker search sized from it.
float casterTopDepth(const LightBasis& basis, std::span<const Bounds> casterBounds, float fallback)
{
    if (casterBounds.empty())
        return fallback;
    float top = std::numeric_limits<float>::max();
    for (const Bounds& caster : casterBounds)
        top = std::min(top, lightSpaceBounds(basis, caster).min.z);
    return top;
}

// The projection's texture-space depth row (t22, t32'): depth = t22 * viewZ + t32, with t32' = t32 + t22 (near -
// casterTop), so that orthographicDistanceFromNear(depth, row) is the distance past the casters' top (the blocker
// search's receiver depth), and differences of two depths stay world distances.
glm::vec2 depthRow(const DirectionalShadowCascade& fit, float casterTop, const rhi::Conventions& conventions)
{
    const glm::mat4 toTexture = conventions.clipToTexture() * fit.projection;
    return {toTexture[2][2], toTexture[3][2] + toTexture[2][2] * (fit.nearDepth - casterTop)};
}

void fillSoftUniforms(DirectionalShadowPlan& plan, const ShadowSettings& settings, const rhi::Conventions& conventions,
                      std::span<const Bounds> casterBounds)
{
    DirectionalShadowUniforms& u = plan.uniforms;
    u.soft = softShadowUniforms(settings.soft);
    const float atlasFactor = normalBiasFilterFactor(settings.directional.filter);
    for (std::size_t slot = 0; slot < plan.lights.size(); ++slot) {
        const ShadowedDirectionalLight& light = plan.lights[slot];
        u.lightSoft[slot] = {tanHalfAngularDiameter(light.angularDiameter),
                             normalBiasFilterFactor(light.filter) / atlasFactor, 0.0f, 0.0f};
        for (const DirectionalCascadePlan& cascade : light.cascades) {
            const float top = casterTopDepth(cascade.fit.basis, casterBounds, cascade.fit.nearDepth);
            u.tileSoft[cascade.tile] = glm::vec4(lightTexelAnchor(cascade), depthRow(cascade.fit, top, conventions));
        }
    }
}

void fillUniforms(DirectionalShadowPlan& plan, const ShadowSettings& settings)
{
    DirectionalShadowUniforms& u = plan.uniforms;
    const auto atlasSize = static_cast<float>(plan.atlas.atlasSize());
    const auto tileSize = static_cast<float>(plan.atlas.tileSize());
    u.atlasSize = {atlasSize, 1.0f / atlasSize, tileSize, 1.0f / tileSize};
    u.distanceFade = shadowDistanceFade(settings);
    u.config = {static_cast<int>(plan.splits.count), static_cast<int>(settings.directional.filter),
                static_cast<int>(settings.directional.cascadeBlend), static_cast<int>(plan.lights.size())};
    for (std::size_t i = 0; i < plan.cascadeData.size(); ++i) {
        u.cullingSpheres[i] = plan.cascadeData[i].selectionSphere;
        u.cascadeData[i] = plan.cascadeData[i].data;
    }
    for (std::size_t slot = 0; slot < plan.lights.size(); ++slot) {
        const ShadowedDirectionalLight& light = plan.lights[slot];
        // On the caster side the lit pass looks up where the surface is.
        const float receiverBias = light.normalBiasSide == NormalBiasSide::Receiver ? light.normalBias : 0.0f;
        u.lightShadowData[slot] = {light.strength, receiverBias, static_cast<float>(light.firstTile),
                                   static_cast<float>(light.filter)};
        for (const DirectionalCascadePlan& cascade : light.cascades)
            u.worldToAtlas[cascade.tile] = cascade.worldToAtlas;
    }
}

} // namespace

CasterNormalOffset casterNormalOffset(const DirectionalShadowPlan& plan, const ShadowedDirectionalLight& light,
                                      std::uint32_t cascade)
{
    if (light.normalBiasSide != NormalBiasSide::Caster || cascade >= plan.cascadeData.size())
        return {};
    return {light.normalBias * plan.cascadeData[cascade].data.y, glm::vec4(light.direction, 0.0f)};
}

DirectionalShadowPlan planDirectionalShadows(const ShadowSettings& settings, const rhi::Conventions& conventions,
                                             const ShadowCamera& camera,
                                             std::span<const DirectionalShadowLightInput> lights,
                                             std::span<const Bounds> casterBounds)
{
    validate(settings);
    const DirectionalShadowSettings& directional = settings.directional;
    DirectionalShadowPlan plan;
    plan.splits = cascadeSplits(camera.nearPlane, camera.farPlane, settings.maxDistance, directional.cascadeCount,
                                directional.cascadeRatios);
    plan.shadowSlots.assign(lights.size(), -1);
    const bool distanceReachesPastNear = plan.splits.farOf(plan.splits.count - 1) > camera.nearPlane;
    if (!distanceReachesPastNear)
        plan.report.push_back({std::nullopt, fmt::format("the shadow distance {} does not reach past the camera's "
                                                         "near plane {}",
                                                         settings.maxDistance, camera.nearPlane)});

    std::vector<std::uint32_t> selected;
    for (std::uint32_t i = 0; i < lights.size(); ++i) {
        std::optional<std::string> reason = exclusion(lights[i], selected.size());
        if (!reason && !distanceReachesPastNear)
            reason = "no shadow distance in front of the camera";
        if (reason) {
            plan.report.push_back({i, std::move(*reason)});
            continue;
        }
        plan.shadowSlots[i] = static_cast<int>(selected.size());
        selected.push_back(i);
    }

    const std::uint32_t cascadeCount = directional.cascadeCount;
    plan.atlas = ShadowAtlasLayout(directional.atlasSize, static_cast<std::uint32_t>(selected.size()) * cascadeCount);
    if (!selected.empty()) {
        for (std::uint32_t c = 0; c < cascadeCount; ++c)
            plan.cullingSpheres.push_back(frustumSliceSphere(camera, plan.splits.nearOf(c), plan.splits.farOf(c)));
    }
    const float cullingFactor = cascadeBlendCullingFactor(directional.cascadeFade);
    for (std::uint32_t slot = 0; slot < selected.size(); ++slot) {
        const DirectionalShadowLightInput& input = lights[selected[slot]];
        ShadowedDirectionalLight light{selected[slot],
                                       input.strength,
                                       input.normalBias,
                                       input.slopeScaleBias,
                                       input.nearPlaneOffset,
                                       input.filter.value_or(directional.filter),
                                       input.angularDiameter,
                                       directionalTileIndex(slot, 0, cascadeCount),
                                       {},
                                       input.normalBiasSide,
                                       input.direction};
        const LightBasis basis = lightBasis(input.direction);
        for (std::uint32_t c = 0; c < cascadeCount; ++c) {
            DirectionalCascadePlan cascade;
            cascade.fit = fitDirectionalCascade(plan.cullingSpheres[c], basis, plan.atlas.tileSize(),
                                                input.nearPlaneOffset, casterBounds, conventions);
            cascade.tile = directionalTileIndex(slot, c, cascadeCount);
            cascade.worldToAtlas = worldToAtlas(cascade.fit.viewProjection, cascade.tile, plan.atlas, conventions);
            cascade.viewport = plan.atlas.viewport(cascade.tile);
            const std::optional<Sphere> previous =
                c > 0 ? std::optional<Sphere>(plan.cullingSpheres[c - 1]) : std::nullopt;
            cascade.casters = cullShadowCasters(cascade.fit, casterBounds, previous, cullingFactor);
            light.cascades.push_back(std::move(cascade));
        }
        plan.lights.push_back(std::move(light));
    }
    // The texel size depends on the sphere's radius and the tile size only, so any light's serves.
    if (!plan.lights.empty())
        for (std::uint32_t c = 0; c < cascadeCount; ++c)
            plan.cascadeData.push_back(
                cascadeData(plan.cullingSpheres[c], plan.lights[0].cascades[c].fit.texelSize, directional.filter));
    fillUniforms(plan, settings);
    fillSoftUniforms(plan, settings, conventions, casterBounds);
    return plan;
}

} // namespace penumbra::shadows
