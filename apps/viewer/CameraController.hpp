#pragma once

#include "penumbra/scene/Camera.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace penumbra::viewer {

// One frame of camera input, already freed from the window system.
struct CameraInput {
    glm::vec2 orbit{0.0f}; // pixels dragged with the left button: turn around the target
    glm::vec2 look{0.0f}; // pixels dragged with the right button: turn in place (fly)
    float zoom = 0.0f; // scroll steps, positive towards the target
    glm::vec3 move{0.0f}; // fly keys: x right (D - A), y up (E - Q), z forward (W - S)
    float seconds = 0.0f; // frame time, scales `move`
};

// Orbit and fly camera. It starts as the given camera, bit for bit, so a viewer frame without
// input renders exactly what `penumbra render` renders; the orbit target lies `targetDistance`
// ahead of it.
class CameraController {
public:
    CameraController(const scene::Camera& start, float targetDistance);

    void update(const CameraInput& input);

    const scene::Camera& camera() const { return camera_; }
    const glm::vec3& target() const { return target_; }
    float targetDistance() const { return distance_; }

    // Radians per dragged pixel, zoom factor per scroll step, fly speed in world units per second.
    static constexpr float kTurnPerPixel = 0.005f;
    static constexpr float kZoomPerStep = 0.9f;
    float flySpeed = 5.0f;

private:
    glm::vec3 forward() const;

    scene::Camera camera_;
    glm::vec3 target_;
    float distance_;
    float yaw_; // around world +y, 0 looking down -z
    float pitch_; // above the horizon
};

} // namespace penumbra::viewer
