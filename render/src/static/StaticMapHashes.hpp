#pragma once

#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <cstdint>
#include <vector>

namespace penumbra::render {

// Per map of `plan`: a hash of its frusta (convention-free) and of every static caster in its views as the scene
// holds it (mesh vertices and indices, transform, shadow casting, the material's caster mode, alpha, cutoff,
// double-sidedness and base colour texture), the same in every configuration and process: a bake's key.
std::vector<std::uint64_t> staticMapHashes(const scene::Scene& scene, const shadows::StaticShadowPlan& plan);

} // namespace penumbra::render
