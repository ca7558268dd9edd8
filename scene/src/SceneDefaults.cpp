#include "penumbra/scene/SceneDefaults.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra::scene {
namespace {

// From the target towards the camera: in front, to the right and above, so boxes show three faces.
constexpr glm::vec3 kViewpoint{0.6f, 0.5f, 1.0f};
// Margin around the bounding sphere, so nothing touches the frame's edge.
constexpr float kFramingMargin = 1.1f;

} // namespace

DirectionalLight defaultSun()
{
    return {.name = "default sun", .direction = lightDirection(glm::radians(50.0f), glm::radians(30.0f))};
}

Camera framingCamera(const Bounds& bounds, float fovY)
{
    const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    const float radius = bounds.empty() ? 1.0f : std::max(0.5f * glm::length(bounds.size()), 1e-3f);
    // The sphere fits when its tangent from the camera stays within half the field of view.
    const float distance = kFramingMargin * radius / std::sin(0.5f * fovY);
    Camera camera = lookAt(center + glm::normalize(kViewpoint) * distance, center, fovY);
    // Near half-way to the sphere (but not at zero, for depth precision), far just behind it.
    camera.nearPlane = std::max(0.5f * (distance - radius), 1e-3f * distance);
    camera.farPlane = (distance + radius) * 1.01f;
    return camera;
}

} // namespace penumbra::scene
