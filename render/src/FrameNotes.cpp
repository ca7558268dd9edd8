#include "FrameNotes.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::render {
namespace {

bool hasStaticMap(const shadows::StaticShadowPlan& plan, shadows::LightKind kind, std::uint32_t index)
{
    return std::any_of(plan.maps.begin(), plan.maps.end(), [&](const shadows::StaticShadowMap& map) {
        return map.kind == kind && map.lightIndex == index;
    });
}

// What a light without realtime shadows has: nothing, or its static map alone.
const char* withoutRealtime(const ShadowPlans& plans, shadows::LightKind kind, std::uint32_t index)
{
    return hasStaticMap(plans.staticMaps, kind, index) ? "has static shadows only" : "has no shadows";
}

} // namespace

const std::string& lightName(const scene::Scene& scene, shadows::LightKind kind, std::uint32_t index)
{
    switch (kind) {
    case shadows::LightKind::Spot:
        return scene.spotLights[index].name;
    case shadows::LightKind::Point:
        return scene.pointLights[index].name;
    case shadows::LightKind::Directional:
        break;
    }
    return scene.lights[index].name;
}

std::string localShadowUpdate(const scene::Scene& scene, shadows::LightKind kind, std::uint32_t index,
                              std::string_view reason)
{
    return fmt::format("{} {} ('{}'): {}", scene::lightKindName(kind), index, lightName(scene, kind, index), reason);
}

FrameStats plannedFrameStats(const scene::Scene& scene, const ShadowPlans& plans)
{
    const shadows::ShadowAtlasPack& pack = plans.local.allocation.pack;
    const std::uint64_t atlasTexels = std::uint64_t(plans.local.atlasSize) * plans.local.atlasSize;
    FrameStats stats{.localAtlasUsed = atlasTexels == 0 ? 0.0f : float(double(pack.usedTexels) / double(atlasTexels)),
                     .localAtlasFragmentation = pack.fragmentation,
                     .localLightsLowered = static_cast<std::uint32_t>(plans.local.lowered.size())};
    for (const shadows::ShadowedDirectionalLight& light : plans.directional.lights)
        for (const shadows::DirectionalCascadePlan& cascade : light.cascades)
            stats.casterDrawsWithoutCullingBias += cascade.casters.overlapping;
    const auto count = [&](bool realtime, shadows::LightKind kind, std::uint32_t index) {
        ++(realtime || hasStaticMap(plans.staticMaps, kind, index) ? stats.shadowedLights : stats.lightsWithoutShadow);
    };
    const std::vector<int>& slots = plans.directional.shadowSlots;
    for (std::uint32_t i = 0; i < scene.lights.size(); ++i)
        count(i < slots.size() && slots[i] >= 0, shadows::LightKind::Directional, i);
    for (std::uint32_t i = 0; i < scene.spotLights.size(); ++i)
        count(i < plans.local.spotTiles.size() && plans.local.spotTiles[i] >= 0, shadows::LightKind::Spot, i);
    for (std::uint32_t i = 0; i < scene.pointLights.size(); ++i)
        count(i < plans.local.pointShadows.size() && plans.local.pointShadows[i] >= 0, shadows::LightKind::Point, i);
    return stats;
}

std::vector<std::string> frameNotes(const scene::Scene& scene, const ShadowPlans& plans)
{
    std::vector<std::string> notes;
    for (const shadows::ShadowPlanNote& note : plans.directional.report)
        notes.push_back(
            note.lightIndex
                ? fmt::format("light {} ('{}') {}: {}", *note.lightIndex, scene.lights[*note.lightIndex].name,
                              withoutRealtime(plans, shadows::LightKind::Directional, *note.lightIndex), note.reason)
                : fmt::format("no shadows: {}", note.reason));
    for (std::size_t i = maxLitDirectionalLights; i < scene.lights.size(); ++i)
        notes.push_back(fmt::format("light {} ('{}') is not drawn: beyond the limit of {} directional lights", i,
                                    scene.lights[i].name, maxLitDirectionalLights));
    for (const shadows::LocalShadowNote& note : plans.local.report)
        notes.push_back(fmt::format("{} {} ('{}') {}: {}", scene::lightKindName(note.kind), note.lightIndex,
                                    lightName(scene, note.kind, note.lightIndex),
                                    withoutRealtime(plans, note.kind, note.lightIndex), note.reason));
    for (const shadows::LocalShadowNote& note : plans.local.lowered)
        notes.push_back(fmt::format("{} {} ('{}'): {}", scene::lightKindName(note.kind), note.lightIndex,
                                    lightName(scene, note.kind, note.lightIndex), note.reason));
    for (const shadows::StaticShadowNote& note : plans.staticMaps.report)
        notes.push_back(fmt::format("{} {} ('{}'): {}", scene::lightKindName(note.kind), note.lightIndex,
                                    lightName(scene, note.kind, note.lightIndex), note.reason));
    return notes;
}

std::optional<std::string> uncollectedShadows(const scene::Scene& scene, const shadows::DirectionalShadowPlan& plan,
                                              const shadows::StaticShadowUniforms& staticMaps)
{
    const std::size_t count = std::min<std::size_t>(plan.shadowSlots.size(), maxLitDirectionalLights);
    for (std::size_t i = maxCollectedDirectionalLights; i < count; ++i)
        if (plan.shadowSlots[i] >= 0 || staticMaps.directionalLights[i].tile >= 0)
            return fmt::format("screen-space shadows: directional light {} ('{}') has shadows, but the screen-space "
                               "shadow texture holds lights 0 to {}; the frame is drawn with forward shadows",
                               i, scene.lights[i].name, maxCollectedDirectionalLights - 1);
    return std::nullopt;
}

} // namespace penumbra::render
