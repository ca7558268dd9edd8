#include "CameraController.hpp"

#include "penumbra/scenes/TestScenes.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace penumbra::viewer {
namespace {

constexpr float kTolerance = 1e-4f;

scene::Camera startCamera() { return scene::lookAt({4.0f, 3.0f, 10.0f}, {0.0f, 1.0f, 0.0f}, 1.0f); }

float distanceToTarget(const CameraController& c) { return glm::length(c.target() - c.camera().position); }

TEST(CameraControllerTest, StartsAsTheSceneCameraBitForBitAndStaysWithoutInput)
{
    const scene::Camera start = startCamera();
    CameraController controller(start, 8.0f);
    controller.update({.seconds = 0.016f});
    EXPECT_EQ(controller.camera().position, start.position);
    EXPECT_EQ(controller.camera().forward, start.forward);
    EXPECT_EQ(controller.camera().up, start.up);
    EXPECT_EQ(controller.camera().fovY, start.fovY);
    EXPECT_NEAR(glm::length(controller.target() - (start.position + 8.0f * start.forward)), 0.0f, kTolerance);
}

TEST(CameraControllerTest, OrbitTurnsAroundTheTargetAtTheSameDistance)
{
    CameraController controller(startCamera(), 8.0f);
    const glm::vec3 target = controller.target();
    controller.update({.orbit = {120.0f, -40.0f}});
    EXPECT_NEAR(glm::length(controller.target() - target), 0.0f, kTolerance);
    EXPECT_NEAR(distanceToTarget(controller), 8.0f, kTolerance);
    EXPECT_GT(glm::length(controller.camera().position - startCamera().position), 0.5f);
    // Still looking at the target.
    EXPECT_NEAR(glm::dot(glm::normalize(target - controller.camera().position), controller.camera().forward), 1.0f,
                kTolerance);
}

TEST(CameraControllerTest, DraggingRightTurnsTheViewRight)
{
    CameraController controller(startCamera(), 8.0f);
    const glm::vec3 right = startCamera().right();
    controller.update({.look = {50.0f, 0.0f}});
    EXPECT_GT(glm::dot(controller.camera().forward, right), 0.1f);
}

TEST(CameraControllerTest, LookTurnsInPlace)
{
    CameraController controller(startCamera(), 8.0f);
    controller.update({.look = {-80.0f, 30.0f}});
    EXPECT_NEAR(glm::length(controller.camera().position - startCamera().position), 0.0f, kTolerance);
    EXPECT_LT(glm::dot(controller.camera().forward, startCamera().forward), 0.99f);
}

TEST(CameraControllerTest, ScrollZoomsTowardsTheTarget)
{
    CameraController controller(startCamera(), 8.0f);
    controller.update({.zoom = 2.0f});
    EXPECT_NEAR(distanceToTarget(controller), 8.0f * CameraController::kZoomPerStep * CameraController::kZoomPerStep,
                kTolerance);
    EXPECT_NEAR(glm::dot(controller.camera().forward, startCamera().forward), 1.0f, kTolerance);
}

TEST(CameraControllerTest, FlyKeysMoveAlongTheViewAndScaleWithTime)
{
    CameraController controller(startCamera(), 8.0f);
    controller.update({.move = {0.0f, 0.0f, 1.0f}, .seconds = 0.5f});
    const glm::vec3 moved = controller.camera().position - startCamera().position;
    EXPECT_NEAR(glm::length(moved), controller.flySpeed * 0.5f, kTolerance);
    EXPECT_NEAR(glm::dot(glm::normalize(moved), startCamera().forward), 1.0f, kTolerance);
}

TEST(CameraControllerTest, PitchStopsShortOfStraightUp)
{
    CameraController controller(startCamera(), 8.0f);
    controller.update({.orbit = {0.0f, -100000.0f}});
    EXPECT_LT(controller.camera().forward.y, 0.9999f);
    EXPECT_GT(glm::length(controller.camera().right()), 0.99f);
}

TEST(CameraControllerTest, FrameFitsTheSphereFromTheSameDirectionAndResetReturnsToTheStart)
{
    const scene::Camera start = startCamera();
    CameraController controller(start, 8.0f);
    controller.update({.orbit = {40.0f, 10.0f}});
    const glm::vec3 looking = controller.camera().forward;
    const glm::vec3 center{1.0f, 0.5f, -2.0f};
    controller.update({.frame = true}, center, 0.33f, 16.0f / 9.0f);
    EXPECT_NEAR(glm::length(controller.camera().forward - looking), 0.0f, kTolerance);
    EXPECT_NEAR(glm::length(controller.target() - center), 0.0f, kTolerance);
    // The sphere's outline at 1 / 1.1 of the (vertical, narrower) half field of view, and in front of the near plane.
    const float distance = distanceToTarget(controller);
    EXPECT_NEAR(std::tan(std::asin(0.33f / distance)) / std::tan(0.5f * start.fovY), 1.0f / 1.1f, 1e-3f);
    EXPECT_LT(controller.camera().nearPlane, distance - 0.33f);
    controller.update({.reset = true});
    EXPECT_EQ(controller.camera().position, start.position);
    EXPECT_EQ(controller.camera().forward, start.forward);
}

TEST(CameraControllerTest, FlySpeedFollowsTheSceneAndItsKeys)
{
    CameraController controller(startCamera(), 8.0f);
    controller.flySpeed = CameraController::flySpeedFor(0.33f);
    EXPECT_FLOAT_EQ(controller.flySpeed, 0.165f);
    controller.update({.speedSteps = 2});
    EXPECT_FLOAT_EQ(controller.flySpeed, 0.165f * CameraController::kSpeedStep * CameraController::kSpeedStep);
    const glm::vec3 before = controller.camera().position;
    controller.update({.move = {0.0f, 0.0f, 1.0f}, .seconds = 1.0f});
    EXPECT_NEAR(glm::length(controller.camera().position - before), controller.flySpeed, kTolerance);
}

} // namespace
} // namespace penumbra::viewer
