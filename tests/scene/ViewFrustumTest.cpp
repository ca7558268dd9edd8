#include "penumbra/scene/ViewFrustum.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <random>

namespace penumbra::scene {
namespace {

const Camera kCamera = {.position = {1.0f, 2.0f, 3.0f},
                        .forward = glm::normalize(glm::vec3(0.3f, -0.2f, -1.0f)),
                        .fovY = 1.0f,
                        .nearPlane = 0.5f,
                        .farPlane = 50.0f};
constexpr float kAspect = 16.0f / 9.0f;

Bounds boxAround(const glm::vec3& centre, float half) { return {centre - half, centre + half}; }

glm::vec3 along(float distance) { return kCamera.position + distance * kCamera.forward; }

TEST(ViewFrustumTest, KeepsWhatIsInViewAndDropsWhatLiesBehindBeyondOrBesideIt)
{
    const ViewFrustum frustum(kCamera, kAspect);
    const glm::vec3 right = kCamera.right();
    EXPECT_TRUE(frustum.mayShow(boxAround(along(10.0f), 0.5f)));
    EXPECT_TRUE(frustum.mayShow(boxAround(kCamera.position, 1.0f))); // reaches past the near plane
    EXPECT_TRUE(frustum.mayShow(boxAround(along(50.5f), 1.0f))); // crosses the far plane
    EXPECT_FALSE(frustum.mayShow(boxAround(along(-2.0f), 1.0f))); // behind the eye
    EXPECT_FALSE(frustum.mayShow(boxAround(along(0.2f), 0.1f))); // before the near plane
    EXPECT_FALSE(frustum.mayShow(boxAround(along(60.0f), 1.0f))); // beyond the far plane
    EXPECT_FALSE(frustum.mayShow(boxAround(along(10.0f) + 20.0f * right, 1.0f)));
    EXPECT_FALSE(frustum.mayShow(boxAround(along(10.0f) - 20.0f * right, 1.0f)));
    EXPECT_FALSE(frustum.mayShow(boxAround(along(10.0f) + 20.0f * kCamera.up, 1.0f)));
}

// Against the projection the lit pass draws with: a box none of whose points is inside the clip volume of one of
// its planes is dropped only then, and a box with a corner in view is always kept.
TEST(ViewFrustumTest, AgreesWithThePerspectiveProjection)
{
    const ViewFrustum frustum(kCamera, kAspect);
    const glm::mat4 clip = glm::perspectiveRH_NO(kCamera.fovY, kAspect, kCamera.nearPlane, kCamera.farPlane) *
                           glm::lookAtRH(kCamera.position, kCamera.position + kCamera.forward, kCamera.up);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> offset(-60.0f, 60.0f);
    std::uniform_real_distribution<float> size(0.01f, 5.0f);
    int kept = 0;
    int dropped = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 centre = kCamera.position + glm::vec3(offset(random), offset(random), offset(random));
        const Bounds box = boxAround(centre, size(random));
        bool cornerInView = false;
        // Per clip plane (x, y, z against +-w), whether all eight corners lie outside it.
        bool outsideOnePlane = false;
        for (int plane = 0; plane < 6; ++plane) {
            bool allOutside = true;
            for (const glm::vec3& corner : box.corners()) {
                const glm::vec4 c = clip * glm::vec4(corner, 1.0f);
                const float coordinate = c[plane / 2];
                allOutside = allOutside && (plane % 2 == 0 ? coordinate < -c.w : coordinate > c.w);
            }
            outsideOnePlane = outsideOnePlane || allOutside;
        }
        for (const glm::vec3& corner : box.corners()) {
            const glm::vec4 c = clip * glm::vec4(corner, 1.0f);
            cornerInView = cornerInView || (std::abs(c.x) < 0.999f * c.w && std::abs(c.y) < 0.999f * c.w &&
                                            std::abs(c.z) < 0.999f * c.w);
        }
        const bool shown = frustum.mayShow(box);
        EXPECT_TRUE(shown || !cornerInView) << i;
        EXPECT_TRUE(shown || outsideOnePlane) << i;
        (shown ? kept : dropped) += 1;
    }
    EXPECT_GT(kept, 1000);
    EXPECT_GT(dropped, 1000);
}

} // namespace
} // namespace penumbra::scene
