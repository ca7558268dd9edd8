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
// What the plans alone tell of the frame: its lights (directional, spot and point) with a shadow (a realtime or a
// static map) and without one, the local atlas's use and fragmentation, the lights whose tiles were lowered, and the
// cascade caster draws the culling bias saved.
FrameStats plannedFrameStats(const scene::Scene& scene, const ShadowPlans& plans);
// Why a screen-space frame's directional shadows cannot all be collected (a light past the collected ones has
// realtime or static shadows), or nullopt.
std::optional<std::string> uncollectedShadows(const scene::Scene& scene, const shadows::DirectionalShadowPlan& plan,
                                              const shadows::StaticShadowUniforms& staticMaps);

} // namespace penumbra::render
