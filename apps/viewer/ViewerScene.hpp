#pragma once

#include "penumbra/scene/Scene.hpp"

#include <string>

namespace penumbra::viewer {

// The scene `--scene` names. Today the built-in scenes (apps/common namedScene); glTF paths
// join them here when the loader lands.
scene::Scene loadViewerScene(const std::string& name);

// How far ahead of the scene's camera the orbit target lies: the depth of the scene's centre,
// at least one unit.
float orbitTargetDistance(const scene::Scene& scene);

} // namespace penumbra::viewer
