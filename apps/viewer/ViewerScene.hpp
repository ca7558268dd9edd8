#pragma once

#include "penumbra/scene/Scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace penumbra::viewer {

// The scene `--scene` names: a built-in scene (apps/common namedScene) or a .gltf / .glb file.
// With every light's filter and source size set when `filter` is not empty or `lightSize` is given
// (apps::applyLightOverrides).
struct ViewerScene {
    scene::Scene scene;
    std::vector<std::string> notes; // the glTF loader's (gltf::GltfScene::notes), shown in the panel
};
ViewerScene loadViewerScene(const std::string& name, const std::string& filter = {},
                            std::optional<float> lightSize = std::nullopt);

// How far ahead of the scene's camera the orbit target lies: the depth of the scene's centre,
// at least one unit.
float orbitTargetDistance(const scene::Scene& scene);

} // namespace penumbra::viewer
