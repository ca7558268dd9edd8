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
    int speedSteps = 0; // fly speed steps (+ and - keys): each multiplies it by kSpeedStep or divides by it
    bool frame = false; // F: look at the scene's bounding sphere from where the camera looks, filling the frame
    bool reset = false; // R: back to the camera the view started with
};

// Orbit and fly camera. It starts as the given camera, bit for bit, so a viewer frame without
// input renders exactly what `penumbra render` renders; the orbit target lies `targetDistance`
// ahead of it.
class CameraController {
public:
    CameraController(const scene::Camera& start, float targetDistance);

    // Moves the camera by `input`; `frame` fits the sphere (center, radius) to the picture of aspect `aspect`.
    void update(const CameraInput& input, const glm::vec3& center = glm::vec3(0.0f), float radius = 1.0f,
                float aspect = 1.0f);

    const scene::Camera& camera() const { return camera_; }
    const glm::vec3& target() const { return target_; }
    float targetDistance() const { return distance_; }

    // Radians per dragged pixel, zoom factor per scroll step, fly speed factor per speed step.
    static constexpr float kTurnPerPixel = 0.005f;
    static constexpr float kZoomPerStep = 0.9f;
    static constexpr float kSpeedStep = 1.5f;
    // World units per second: flySpeedFor(the scene's bounding sphere), so the fly keys cross any scene in the same
    // time.
    float flySpeed = 5.0f;
    // Half the sphere's radius per second: the fly keys cross the scene in four seconds.
    static float flySpeedFor(float radius);

private:
    glm::vec3 forward() const;
    void frameSphere(const glm::vec3& center, float radius, float aspect);
    void resetToStart();

    const scene::Camera start_;
    const float startDistance_;

    scene::Camera camera_;
    glm::vec3 target_;
    float distance_;
    float yaw_; // around world +y, 0 looking down -z
    float pitch_; // above the horizon
};

} // namespace penumbra::viewer
