#include "penumbra/scene/SceneDefaults.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra::scene {
namespace {

// From the target towards the camera: in front, to the right and above, so boxes show three faces.
constexpr glm::vec3 kViewpoint{0.6f, 0.5f, 1.0f};
// Room around the framed box, so nothing touches the frame's edge: it fills 1 / 1.1 of the frame.
constexpr float kFramingMargin = 1.1f;

} // namespace

DirectionalLight defaultSun()
{
    return {.name = "default sun", .direction = lightDirection(glm::radians(50.0f), glm::radians(30.0f))};
}

Camera framingCamera(const Bounds& bounds, float fovY)
{
    const Bounds box = bounds.empty() ? Bounds{glm::vec3(-1.0f), glm::vec3(1.0f)} : bounds;
    const glm::vec3 center = box.center();
    const float radius = std::max(0.5f * glm::length(box.size()), 1e-3f);
    // The camera's axes: it looks along -back from center + back * distance.
    const Camera axes = lookAt(center + glm::normalize(kViewpoint), center, fovY);
    const glm::vec3 back = -axes.forward, right = axes.right(), up = glm::cross(back, right);
    // Every corner within the vertical field of view (shrunk by the margin) in x and in y, so the box fills most of
    // the frame's height, or of its width where the frame is square: a corner at (x, y) across and z towards the
    // camera needs |x| / (distance - z) <= tan(fovY / 2) / margin.
    const float slope = std::tan(0.5f * fovY) / kFramingMargin;
    float distance = 0.0f;
    for (const glm::vec3& corner : box.corners()) {
        const glm::vec3 d = corner - center;
        const float across = std::max(std::abs(glm::dot(d, right)), std::abs(glm::dot(d, up)));
        distance = std::max(distance, across / slope + glm::dot(d, back));
    }
    Camera camera = lookAt(center + back * distance, center, fovY);
    // Near half-way to the bounding sphere (but not at zero, for depth precision), far just behind it.
    camera.nearPlane = std::max(0.5f * (distance - radius), 1e-3f * distance);
    camera.farPlane = (distance + radius) * 1.01f;
    return camera;
}

} // namespace penumbra::scene
