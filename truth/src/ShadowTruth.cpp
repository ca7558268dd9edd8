#include "penumbra/truth/ShadowTruth.hpp"

#include "penumbra/truth/SoftShadowTruth.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/CascadeSelection.hpp"
#include "penumbra/shadows/LocalLightProjection.hpp"
#include "penumbra/shadows/NormalOffset.hpp"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra::truth {
namespace {

// The perspective view's texel at the position's distance from its light plane (a perspective texel grows
// linearly with that distance).
float perspectiveTexel(const glm::mat4& projection, std::uint32_t tileSize, glm::vec3 axis, glm::vec3 fromLight)
{
    return shadows::texelSizeAtUnitDistance(projection, tileSize) * glm::dot(fromLight, axis);
}

float directionalTexel(const shadows::DirectionalShadowPlan& plan, std::uint32_t index, const scene::Camera& camera,
                       glm::vec3 position)
{
    if (index >= plan.shadowSlots.size() || plan.shadowSlots[index] < 0)
        return 0.0f;
    const auto slot = static_cast<std::uint32_t>(plan.shadowSlots[index]);
    const auto& cascades = plan.lights[slot].cascades;
    if (plan.uniforms.cascadeProjection != shadows::CascadeProjection::Stable) {
        // The band of the point's view depth, or depth fit's first tile of the light's that holds it, as the lit
        // shader selects them.
        const float viewDepth = glm::dot(position - camera.position, camera.forward);
        const std::uint32_t cascade = shadows::selectCascade(plan.uniforms, position, viewDepth, slot).index;
        return cascade < cascades.size() ? cascades[cascade].fit.texelSize : 0.0f;
    }
    // The first cascade whose culling sphere holds the point (not shrunk by the filter: the edge margins of the
    // ray cast take the coarser texel only past the sphere).
    for (const shadows::DirectionalCascadePlan& cascade : cascades) {
        const glm::vec3 offset = position - cascade.fit.cullingSphere.centre;
        if (glm::dot(offset, offset) < cascade.fit.cullingSphere.radius * cascade.fit.cullingSphere.radius)
            return cascade.fit.texelSize;
    }
    return 0.0f;
}

float pointTexel(const render::ShadowPlans& plans, std::uint32_t cubeFaceSize, const scene::PointLight& light,
                 int shadow, glm::vec3 position)
{
    const glm::vec3 fromLight = position - light.position;
    const shadows::CubeFace face = shadows::cubeFace(fromLight);
    const glm::vec3 axis = shadows::cubeFaceAxis(face);
    if (!plans.local.cubes.empty())
        return perspectiveTexel(
            plans.local.cubes.at(static_cast<std::size_t>(shadow)).faces[static_cast<std::size_t>(face)].projection,
            cubeFaceSize, axis, fromLight);
    const std::size_t tile = static_cast<std::size_t>(shadow) + static_cast<std::size_t>(face);
    const shadows::LocalAtlasTile& t = plans.local.tiles.at(tile);
    return perspectiveTexel(t.view.projection, static_cast<std::uint32_t>(t.viewport.width), axis, fromLight);
}

} // namespace

RenderedVisibility renderedVisibility(const rhi::Image& view)
{
    if (view.format != rhi::Format::RGBA8)
        throw rhi::Error("renderedVisibility: the visibility view is RGBA8");
    RenderedVisibility v{view.width, view.height, std::vector<float>(std::size_t(view.width) * view.height),
                         std::vector<std::uint8_t>(std::size_t(view.width) * view.height)};
    for (std::size_t i = 0; i < v.lit.size(); ++i) {
        const std::byte* texel = view.bytes.data() + 4 * i;
        v.lit[i] = static_cast<float>(std::to_integer<int>(texel[0])) / 255.0f;
        v.decided[i] = std::to_integer<int>(texel[3]) >= 128 ? 1 : 0;
    }
    return v;
}

float directionalTexelsPerMetre(const shadows::DirectionalShadowPlan& plan, std::uint32_t lightIndex,
                                const scene::Camera& camera, float aspect, float viewDepth)
{
    const glm::vec3 right = camera.right();
    const glm::vec3 up = glm::normalize(glm::cross(right, camera.forward));
    const float halfHeight = viewDepth * std::tan(0.5f * camera.fovY);
    constexpr int kColumns = 16, kRows = 9;
    float sum = 0.0f;
    int covered = 0;
    for (int row = 0; row < kRows; ++row)
        for (int column = 0; column < kColumns; ++column) {
            const float x = (2.0f * (static_cast<float>(column) + 0.5f) / kColumns - 1.0f) * halfHeight * aspect;
            const float y = (2.0f * (static_cast<float>(row) + 0.5f) / kRows - 1.0f) * halfHeight;
            const float texel = directionalTexel(plan, lightIndex, camera,
                                                 camera.position + camera.forward * viewDepth + right * x + up * y);
            if (texel > 0.0f) {
                sum += 1.0f / texel;
                ++covered;
            }
        }
    return covered > 0 ? sum / static_cast<float>(covered) : 0.0f;
}

OnScreenTexelDensity directionalTexelsOnScreen(const shadows::DirectionalShadowPlan& plan, std::uint32_t lightIndex,
                                               const scene::Camera& camera, const CpuGBuffer& gbuffer)
{
    std::vector<float> texels;
    for (const GBufferSample& sample : gbuffer.samples) {
        const float texel = sample.hit() ? directionalTexel(plan, lightIndex, camera, sample.position) : 0.0f;
        if (texel > 0.0f)
            texels.push_back(1.0f / texel);
    }
    if (texels.empty())
        return {};
    const auto at = [&](std::size_t rank) {
        std::nth_element(texels.begin(), texels.begin() + static_cast<std::ptrdiff_t>(rank), texels.end());
        return texels[rank];
    };
    return {at(texels.size() / 2), at(texels.size() / 10), texels.size()};
}

float shadowTexelSize(const render::ShadowPlans& plans, const shadows::ShadowSettings& settings,
                      const scene::Scene& scene, const scene::LightRef& light, glm::vec3 position)
{
    switch (light.kind) {
    case scene::LightKind::Directional: {
        // A static map decides with the realtime shadow (the darker of the two), or alone beyond the cascades.
        float texel = directionalTexel(plans.directional, light.index, scene.camera, position);
        for (const shadows::StaticShadowMap& map : plans.staticMaps.maps)
            if (map.kind == shadows::LightKind::Directional && map.lightIndex == light.index)
                texel = std::max(texel, map.texelSize);
        return texel;
    }
    case scene::LightKind::Spot: {
        const int tile = plans.local.spotTiles.at(light.index);
        if (tile < 0)
            return 0.0f;
        const scene::SpotLight& spot = scene.spotLights.at(light.index);
        const shadows::LocalAtlasTile& t = plans.local.tiles.at(static_cast<std::size_t>(tile));
        return perspectiveTexel(t.view.projection, static_cast<std::uint32_t>(t.viewport.width), spot.direction,
                                position - spot.position);
    }
    case scene::LightKind::Point: {
        const int shadow = plans.local.pointShadows.at(light.index);
        return shadow < 0
                   ? 0.0f
                   : pointTexel(plans, settings.local.cubeMapSize, scene.pointLights.at(light.index), shadow, position);
    }
    }
    return 0.0f;
}

ShadowRayFrom truthRays(const scene::Scene& scene, const scene::LightRef& light)
{
    switch (light.kind) {
    case scene::LightKind::Directional:
        return raysTowards(scene.lights.at(light.index));
    case scene::LightKind::Spot:
        return raysTowards(scene.spotLights.at(light.index).position);
    case scene::LightKind::Point:
        return raysTowards(scene.pointLights.at(light.index).position);
    }
    return raysTowards(scene.lights.at(light.index));
}

float shadowEdgeMarginTexels(shadows::ShadowFilter filter)
{
    const float reach = shadows::normalBiasFilterFactor(filter);
    return reach * (1.0f + std::sqrt(2.0f)) + 0.5f;
}

float lookupFootprintTexels(shadows::ShadowFilter filter) { return shadows::normalBiasFilterFactor(filter) + 0.5f; }

LightTruthTrace traceLightTruth(const scene::Scene& scene, const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                const render::ShadowPlans& plans, const shadows::ShadowSettings& settings,
                                const scene::LightRef& light, const TraceProgress& progress)
{
    const ShadowRayFrom rays = truthRays(scene, light);
    // The light's own filter (its shadowFilter, else the atlas's): its reach sets the lit pass's normal offset.
    const shadows::ShadowFilter filter = plannedShadowFilter(plans, light);
    const float margin = shadowEdgeMarginTexels(filter);
    // Half the rows' progress for each of the two traces.
    const auto half = [&](std::uint32_t offset) -> TraceProgress {
        if (!progress)
            return {};
        return [&, offset](std::uint32_t done, std::uint32_t rows) { progress(offset + done, 2 * rows); };
    };
    LightTruthTrace t{traceVisibility(scene, shadowRays, gbuffer, rays, kShadowRayOffset, half(0)),
                      {},
                      std::vector<LookupFootprint>(gbuffer.samples.size()),
                      rays};
    std::vector<float> edgeRadii(gbuffer.samples.size(), 0.0f);
    for (std::size_t i = 0; i < gbuffer.samples.size(); ++i) {
        const GBufferSample& sample = gbuffer.samples[i];
        if (sample.object == kNoObject)
            continue;
        const float texel = shadowTexelSize(plans, settings, scene, light, sample.position);
        edgeRadii[i] = margin * texel;
        const glm::vec3 towardsLight = rays(sample.position).direction;
        t.footprints[i] = {sample.position +
                               shadows::receiverNormalOffset(sample.normal, towardsLight,
                                                             shadows::normalOffsetReach(1.0f, texel, filter)),
                           lookupFootprintTexels(filter) * texel};
    }
    t.shadowEdges = traceShadowEdges(shadowRays, gbuffer, t.visibility, rays, edgeRadii, half(gbuffer.height));
    return t;
}

TruthComparison compareLightTruth(const LightTruthTrace& trace, const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                  const RenderedVisibility& rendered)
{
    TruthComparison c = compareWithTruth(gbuffer, trace.visibility, rendered, trace.shadowEdges);
    confirmDisagreements(c, shadowRays, gbuffer, trace.visibility, trace.rays, trace.footprints);
    return c;
}

std::string lightLabel(const scene::Scene& scene, const scene::LightRef& light)
{
    const std::string& name = light.kind == scene::LightKind::Directional ? scene.lights.at(light.index).name
                              : light.kind == scene::LightKind::Spot      ? scene.spotLights.at(light.index).name
                                                                          : scene.pointLights.at(light.index).name;
    return name.empty() ? fmt::format("{} {}", scene::lightKindName(light.kind), light.index) : name;
}

} // namespace penumbra::truth
