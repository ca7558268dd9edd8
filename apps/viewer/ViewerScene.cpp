#include "ViewerScene.hpp"

#include "LightOverrides.hpp"
#include "ShadowScene.hpp"

#include "penumbra/gltf/GltfLoader.hpp"

#include <algorithm>
#include <filesystem>
#include <glm/geometric.hpp>

namespace penumbra::viewer {

ViewerScene loadViewerScene(const std::string& name, const std::string& filter, std::optional<float> lightSize)
{
    const std::filesystem::path extension = std::filesystem::path(name).extension();
    ViewerScene loaded;
    if (extension == ".gltf" || extension == ".glb") {
        gltf::GltfScene file = gltf::loadGltf(name);
        loaded.scene = std::move(file.scene);
        loaded.notes = std::move(file.notes);
    } else {
        loaded.scene = apps::namedScene(name);
    }
    apps::applyLightOverrides(loaded.scene, filter, lightSize);
    return loaded;
}

float orbitTargetDistance(const scene::Scene& scene)
{
    const scene::Bounds bounds = scene.worldBounds();
    if (bounds.empty())
        return 1.0f;
    return std::max(1.0f, glm::dot(bounds.center() - scene.camera.position, scene.camera.forward));
}

} // namespace penumbra::viewer
