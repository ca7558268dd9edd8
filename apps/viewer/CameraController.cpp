#include "CameraController.hpp"

#include "penumbra/scene/SceneDefaults.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace penumbra::viewer {
namespace {

// Just short of straight up or down, where yaw and the view's up vector would degenerate.
constexpr float kMaxPitch = 1.55f;

} // namespace

CameraController::CameraController(const scene::Camera& start, float targetDistance)
    : start_(start), startDistance_(targetDistance), camera_(start),
      target_(start.position + start.forward * targetDistance), distance_(targetDistance),
      yaw_(std::atan2(start.forward.x, -start.forward.z)), pitch_(std::asin(std::clamp(start.forward.y, -1.0f, 1.0f)))
{
}

float CameraController::flySpeedFor(float radius) { return std::max(0.5f * radius, 1e-3f); }

void CameraController::resetToStart()
{
    camera_ = start_;
    target_ = start_.position + start_.forward * startDistance_;
    distance_ = startDistance_;
    yaw_ = std::atan2(start_.forward.x, -start_.forward.z);
    pitch_ = std::asin(std::clamp(start_.forward.y, -1.0f, 1.0f));
}

void CameraController::frameSphere(const glm::vec3& center, float radius, float aspect)
{
    target_ = center;
    distance_ = scene::framingDistance(radius, camera_.fovY, aspect);
    // Near half-way to the sphere and far behind it, as scene::framingCamera sets them, so a small model is not cut
    // by a near plane meant for a large scene, nor a large one by its far plane.
    camera_.nearPlane = std::max(0.5f * (distance_ - radius), 1e-3f * distance_);
    camera_.farPlane = std::max(camera_.farPlane, (distance_ + radius) * 1.01f);
}

glm::vec3 CameraController::forward() const
{
    return {std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), -std::cos(pitch_) * std::cos(yaw_)};
}

void CameraController::update(const CameraInput& input, const glm::vec3& center, float radius, float aspect)
{
    flySpeed *= std::pow(kSpeedStep, float(input.speedSteps));
    if (input.reset) {
        resetToStart();
        return;
    }
    if (input.frame)
        frameSphere(center, radius, aspect);
    const bool orbiting = input.orbit != glm::vec2(0.0f);
    const bool looking = input.look != glm::vec2(0.0f);
    const bool moving = input.move != glm::vec3(0.0f) && input.seconds > 0.0f;
    if (!orbiting && !looking && !moving && input.zoom == 0.0f && !input.frame)
        return; // keep the camera bit-identical while nothing happens

    const glm::vec2 turn = (input.orbit + input.look) * kTurnPerPixel;
    yaw_ += turn.x;
    pitch_ = std::clamp(pitch_ - turn.y, -kMaxPitch, kMaxPitch);
    const glm::vec3 f = forward();
    if (looking) // fly: the eye stays, the target swings round it
        target_ = camera_.position + f * distance_;
    distance_ *= std::pow(kZoomPerStep, input.zoom);

    const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 step = (right * input.move.x + glm::vec3(0.0f, 1.0f, 0.0f) * input.move.y + f * input.move.z) *
                           flySpeed * input.seconds;
    target_ += step;
    camera_.forward = f;
    camera_.up = {0.0f, 1.0f, 0.0f};
    camera_.position = target_ - f * distance_;
}

} // namespace penumbra::viewer
