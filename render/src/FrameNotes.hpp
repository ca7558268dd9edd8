#pragma once

#include "penumbra/render/SceneRenderer.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::render {

const std::string& lightName(const scene::Scene& scene, shadows::LightKind kind, std::uint32_t index);
// Lights drawn without shadows, or not drawn at all, and why.
std::vector<std::string> frameNotes(const scene::Scene& scene, const ShadowPlans& plans);
// "spot light 3 ('lamp'): a caster in its view changed": a light whose realtime tiles the frame drew again.
std::string localShadowUpdate(const scene::Scene& scene, shadows::LightKind kind, std::uint32_t index,
                              std::string_view reason);
// The frame's lights (directional, spot and point) with a shadow (a realtime or a static map) and without one.
struct ShadowedLightCounts {
    std::uint32_t shadowed = 0;
    std::uint32_t withoutShadow = 0;
};
ShadowedLightCounts shadowedLightCounts(const scene::Scene& scene, const ShadowPlans& plans);
// Why a screen-space frame's directional shadows cannot all be collected (a light past the collected ones has
// realtime or static shadows), or nullopt.
std::optional<std::string> uncollectedShadows(const scene::Scene& scene, const shadows::DirectionalShadowPlan& plan,
                                              const shadows::StaticShadowUniforms& staticMaps);

} // namespace penumbra::render
