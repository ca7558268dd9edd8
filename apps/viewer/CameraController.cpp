#include "CameraController.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace penumbra::viewer {
namespace {

// Just short of straight up or down, where yaw and the view's up vector would degenerate.
constexpr float kMaxPitch = 1.55f;

} // namespace

CameraController::CameraController(const scene::Camera& start, float targetDistance)
    : camera_(start), target_(start.position + start.forward * targetDistance), distance_(targetDistance),
      yaw_(std::atan2(start.forward.x, -start.forward.z)), pitch_(std::asin(std::clamp(start.forward.y, -1.0f, 1.0f)))
{
}

glm::vec3 CameraController::forward() const
{
    return {std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), -std::cos(pitch_) * std::cos(yaw_)};
}

void CameraController::update(const CameraInput& input)
{
    const bool orbiting = input.orbit != glm::vec2(0.0f);
    const bool looking = input.look != glm::vec2(0.0f);
    const bool moving = input.move != glm::vec3(0.0f) && input.seconds > 0.0f;
    if (!orbiting && !looking && !moving && input.zoom == 0.0f)
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
