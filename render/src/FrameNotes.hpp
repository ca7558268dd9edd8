#pragma once

#include "penumbra/render/SceneRenderer.hpp"

#include <optional>
#include <string>
#include <vector>

namespace penumbra::render {

const std::string& lightName(const scene::Scene& scene, shadows::ShadowLightKind kind, std::uint32_t index);
// Lights drawn without shadows, or not drawn at all, and why.
std::vector<std::string> frameNotes(const scene::Scene& scene, const ShadowPlans& plans);
// Why a screen-space frame's directional shadows cannot all be collected (a light past the collected ones has
// realtime or static shadows), or nullopt.
std::optional<std::string> uncollectedShadows(const scene::Scene& scene, const shadows::DirectionalShadowPlan& plan,
                                              const shadows::StaticShadowUniforms& staticMaps);

} // namespace penumbra::render
