#include "penumbra/scene/SceneDefaults.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra::scene {
namespace {

// From the target towards the camera: in front, to the right and above, so boxes show three faces.
constexpr glm::vec3 kViewpoint{0.6f, 0.5f, 1.0f};
// Room around the framed sphere, so nothing touches the frame's edge: its outline reaches 1 / 1.1 of the way from
// the centre to the nearer edge.
constexpr float kFramingMargin = 1.1f;
constexpr glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};

} // namespace

DirectionalLight defaultSun(const Camera& camera)
{
    // The camera's forward direction on the ground; looking (nearly) straight down, its picture's up.
    glm::vec3 ahead = camera.forward - kWorldUp * glm::dot(camera.forward, kWorldUp);
    if (glm::length(ahead) < 1e-3f)
        ahead = camera.up - kWorldUp * glm::dot(camera.up, kWorldUp);
    ahead = glm::length(ahead) < 1e-3f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::normalize(ahead);
    const glm::vec3 left = glm::cross(kWorldUp, ahead);
    const float elevation = glm::radians(kDefaultSunElevationDegrees);
    const float azimuth = glm::radians(kDefaultSunAzimuthDegrees);
    // From the scene towards the sun: behind the camera, turned to its left, raised above the horizon.
    const glm::vec3 towardsSun =
        std::cos(elevation) * (-std::cos(azimuth) * ahead + std::sin(azimuth) * left) + std::sin(elevation) * kWorldUp;
    return {.name = "default sun", .direction = -glm::normalize(towardsSun)};
}

float framingDistance(float radius, float fovY, float aspect)
{
    // The narrower half field of view, as a tangent: a frame's half width is aspect x its half height.
    const float halfSlope = std::tan(0.5f * fovY) * std::min(1.0f, aspect);
    // A sphere of radius r at distance d has an outline at angle asin(r / d) from its centre: put that outline at
    // the slope halfSlope / margin, so d = r / sin(atan(halfSlope / margin)).
    return radius / std::sin(std::atan(halfSlope / kFramingMargin));
}

Camera framingCamera(const Bounds& bounds, float fovY, float aspect)
{
    const Bounds box = bounds.empty() ? Bounds{glm::vec3(-1.0f), glm::vec3(1.0f)} : bounds;
    const glm::vec3 center = box.center();
    const float radius = std::max(0.5f * glm::length(box.size()), 1e-3f);
    const float distance = framingDistance(radius, fovY, aspect);
    const glm::vec3 back = glm::normalize(kViewpoint);
    Camera camera = lookAt(center + back * distance, center, fovY);
    // Near half-way to the bounding sphere (but not at zero, for depth precision), far just behind it.
    camera.nearPlane = std::max(0.5f * (distance - radius), 1e-3f * distance);
    camera.farPlane = (distance + radius) * 1.01f;
    return camera;
}

} // namespace penumbra::scene
