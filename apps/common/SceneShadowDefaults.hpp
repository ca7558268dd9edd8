#pragma once

#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>

namespace penumbra::apps {

// The shadow atlases' sides when no settings are given, those of the static maps' defaults
// (shadows::StaticShadowSettings): the directional atlas 4096 texels (2048 per cascade of four; Godot's directional
// shadow default is 4096^2, Bevy's 2048^2 per cascade), 64 MiB of D32F depth; the spot and point atlas 2048 (512 per
// tile of 16), 16 MiB; a small share of any discrete GPU of the last decade. The design documents' 1024 stays a flag
// away (--shadow-defaults documents).
inline constexpr std::uint32_t kSceneAtlasSize = shadows::StaticShadowSettings{}.directionalAtlasSize;
inline constexpr std::uint32_t kSceneLocalAtlasSize = shadows::StaticShadowSettings{}.localAtlasSize;

// The view depth that the shadows of `scene` seen from its camera need: that of the farthest corner of its bounds,
// beyond which nothing is there to shadow, divided by 1 - `distanceFade` so the fade starts behind it; at most the
// camera's far plane, and 0 for empty bounds or bounds wholly behind the camera.
float sceneShadowDistance(const scene::Scene& scene, float distanceFade);

// The design documents' defaults (shadows::ShadowSettings{}) fitted to `scene`: the shadow distance
// sceneShadowDistance (the documents' 100 m where that is 0), atlases of kSceneAtlasSize and kSceneLocalAtlasSize.
shadows::ShadowSettings sceneShadowSettings(const scene::Scene& scene);

} // namespace penumbra::apps
