#include "SceneShadowDefaults.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace penumbra::apps {

float sceneShadowDistance(const scene::Scene& scene, float distanceFade)
{
    const scene::Bounds bounds = scene.worldBounds();
    if (bounds.empty())
        return 0.0f;
    const scene::Camera& camera = scene.camera;
    const glm::vec3 forward = glm::normalize(camera.forward);
    float farthest = 0.0f;
    for (const glm::vec3& corner : bounds.corners())
        farthest = std::max(farthest, glm::dot(corner - camera.position, forward));
    return std::min(farthest / std::max(1.0f - distanceFade, 1e-3f), camera.farPlane);
}

shadows::ShadowSettings sceneShadowSettings(const scene::Scene& scene)
{
    shadows::ShadowSettings settings;
    // ShadowSettings' least shadow distance is 0.001; a scene that needs less than a centimetre keeps the default.
    if (const float distance = sceneShadowDistance(scene, settings.distanceFade); distance > 0.01f)
        settings.maxDistance = distance;
    settings.directional.atlasSize = kSceneAtlasSize;
    settings.local.atlasSize = kSceneLocalAtlasSize;
    return settings;
}

} // namespace penumbra::apps
