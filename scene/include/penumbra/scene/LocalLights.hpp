#pragma once

#include "penumbra/scene/Scene.hpp"

#include <cstdint>

namespace penumbra::scene {

// A scene's local lights in one order: its spot lights, then its point lights (the order shadow planning takes them
// in). `--lights N` keeps the first N of them.
std::uint32_t localLightCount(const Scene& scene);

// Keeps the first `count` local lights (spot lights first, then point lights) and removes the rest; a count of at
// least localLightCount keeps them all. Directional lights stay.
void keepFirstLocalLights(Scene& scene, std::uint32_t count);

} // namespace penumbra::scene
