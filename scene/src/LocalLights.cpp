#include "penumbra/scene/LocalLights.hpp"

#include <algorithm>

namespace penumbra::scene {

std::uint32_t localLightCount(const Scene& scene)
{
    return static_cast<std::uint32_t>(scene.spotLights.size() + scene.pointLights.size());
}

void keepFirstLocalLights(Scene& scene, std::uint32_t count)
{
    const std::size_t spots = std::min<std::size_t>(count, scene.spotLights.size());
    scene.spotLights.resize(spots);
    scene.pointLights.resize(std::min<std::size_t>(count - spots, scene.pointLights.size()));
}

} // namespace penumbra::scene
