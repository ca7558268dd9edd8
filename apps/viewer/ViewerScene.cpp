#include "ViewerScene.hpp"

#include "ShadowScene.hpp"

#include "penumbra/scene/GltfLoader.hpp"

#include <algorithm>
#include <filesystem>
#include <glm/geometric.hpp>

namespace penumbra::viewer {

scene::Scene loadViewerScene(const std::string& name)
{
    const std::filesystem::path extension = std::filesystem::path(name).extension();
    if (extension == ".gltf" || extension == ".glb")
        return scene::loadGltf(name).scene;
    return apps::namedScene(name);
}

float orbitTargetDistance(const scene::Scene& scene)
{
    const scene::Bounds bounds = scene.worldBounds();
    if (bounds.empty())
        return 1.0f;
    return std::max(1.0f, glm::dot(bounds.center() - scene.camera.position, scene.camera.forward));
}

} // namespace penumbra::viewer
