#pragma once

#include "penumbra/scene/Scene.hpp"

#include <string>

namespace penumbra::viewer {

// The scene `--scene` names: a built-in scene (apps/common namedScene) or a .gltf / .glb file.
scene::Scene loadViewerScene(const std::string& name);

// How far ahead of the scene's camera the orbit target lies: the depth of the scene's centre,
// at least one unit.
float orbitTargetDistance(const scene::Scene& scene);

} // namespace penumbra::viewer
