#include "ShadowTestSupport.hpp"
#include "penumbra/shadows/AtlasMatrix.hpp"
#include "penumbra/shadows/DirectionalCascadeFit.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

using testing::randomCamera;

const rhi::Conventions defaultConventions{rhi::DepthRange::ZeroToOne, false};

TEST(CascadeFit, EverySliceCornerIsInsideItsSphere)
{
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> ratio(0.0f, 1.0f);
    for (int trial = 0; trial < 500; ++trial) {
        const ShadowCamera camera = randomCamera(rng);
        const float a = camera.nearPlane + ratio(rng) * 100.0f;
        const float b = a + ratio(rng) * 100.0f;
        const Sphere sphere = frustumSliceSphere(camera, a, b);
        float farthest = 0.0f;
        for (const glm::vec3& corner : frustumSliceCorners(camera, a, b)) {
            const float d = glm::length(corner - sphere.centre);
            EXPECT_LE(d, sphere.radius * (1.0f + 1e-5f) + 1e-4f) << "trial " << trial;
            farthest = std::max(farthest, d);
        }
        // Tight: the farthest corner is on the sphere (it is the smallest enclosing sphere).
        EXPECT_NEAR(farthest, sphere.radius, sphere.radius * 1e-5f + 1e-4f) << "trial " << trial;
    }
}

TEST(CascadeFit, SphereRadiusAndTexelSizeDoNotChangeWhenTheCameraRotates)
{
    std::mt19937 rng(2);
    ShadowCamera camera = randomCamera(rng);
    const Sphere reference = frustumSliceSphere(camera, 5.0f, 20.0f);
    const float referenceTexel =
        fitDirectionalCascade(reference, lightSpaceCasters(lightBasis({0.3f, -1.0f, 0.2f}), {}), 512, 0.0f,
                              defaultConventions)
            .texelSize;
    for (int trial = 0; trial < 100; ++trial) {
        testing::randomOrientation(rng, camera.forward, camera.up);
        const Sphere rotated = frustumSliceSphere(camera, 5.0f, 20.0f);
        EXPECT_EQ(rotated.radius, reference.radius);
        const DirectionalShadowCascade fit =
            fitDirectionalCascade(rotated, lightSpaceCasters(lightBasis({0.3f, -1.0f, 0.2f}), {}), 512, 0.0f,
                                  defaultConventions);
        EXPECT_EQ(fit.texelSize, referenceTexel);
    }
}

// Stable fit: a fixed world point keeps its sub-texel position in the atlas while the camera translates.
TEST(CascadeFit, TranslatingTheCameraMovesShadowTexelsByWholeTexelsOnly)
{
    std::mt19937 rng(3);
    const ShadowAtlasLayout layout(2048, 4);
    for (const rhi::Conventions& conventions : testing::allConventions()) {
        ShadowCamera camera = testing::uprightCamera(glm::vec3(10.0f, 3.0f, -7.0f), glm::vec3(0.4f, -0.2f, -1.0f));
        const glm::vec3 light = glm::normalize(glm::vec3(-0.5f, -1.0f, 0.3f));
        const glm::vec3 point = camera.position + camera.forward * 6.0f + glm::vec3(0.3f, 0.1f, -0.2f);
        auto atlasTexel = [&](const ShadowCamera& c) {
            const Sphere sphere = frustumSliceSphere(c, c.nearPlane, 12.0f);
            const DirectionalShadowCascade fit = fitDirectionalCascade(sphere, lightSpaceCasters(lightBasis(light), {}),
                                                                       layout.tileSize(), 0.0f, conventions);
            const glm::vec4 p = worldToAtlas(fit.viewProjection, 1, layout, conventions) * glm::vec4(point, 1.0f);
            return std::pair{glm::vec2(p) * static_cast<float>(layout.atlasSize()), fit.texelSize};
        };
        const auto [reference, texel] = atlasTexel(camera);
        std::uniform_real_distribution<float> step(-3.0f, 3.0f);
        int moved = 0;
        for (int trial = 0; trial < 200; ++trial) {
            ShadowCamera translated = camera;
            translated.position += glm::vec3(step(rng), step(rng), step(rng)) * texel;
            const glm::vec2 delta = atlasTexel(translated).first - reference;
            EXPECT_NEAR(delta.x, std::round(delta.x), 2e-3f) << testing::conventionName(conventions);
            EXPECT_NEAR(delta.y, std::round(delta.y), 2e-3f) << testing::conventionName(conventions);
            moved += std::round(delta.x) != 0.0f || std::round(delta.y) != 0.0f;
        }
        EXPECT_GT(moved, 0); // the snapped tile did follow the camera
    }
}

TEST(CascadeFit, TheSphereLiesInsideItsTileAndItsCentreInTheMiddle)
{
    std::mt19937 rng(4);
    const ShadowAtlasLayout layout(1024, 16);
    for (int trial = 0; trial < 50; ++trial) {
        const ShadowCamera camera = randomCamera(rng);
        const Sphere sphere = frustumSliceSphere(camera, camera.nearPlane, camera.nearPlane + 30.0f);
        const DirectionalShadowCascade fit =
            fitDirectionalCascade(sphere, lightSpaceCasters(lightBasis(testing::randomUnit(rng)), {}),
                                  layout.tileSize(), 0.5f, defaultConventions);
        const std::uint32_t tile = static_cast<std::uint32_t>(trial % 16);
        const glm::mat4 m = worldToAtlas(fit.viewProjection, tile, layout, defaultConventions);
        const glm::vec2 low(layout.tileOffset(tile));
        const glm::vec2 high = low + static_cast<float>(layout.tileSize());
        const float size = static_cast<float>(layout.atlasSize());
        const glm::vec2 centre = glm::vec2(m * glm::vec4(sphere.centre, 1.0f)) * size;
        EXPECT_LE(glm::length(centre - 0.5f * (low + high)), 0.71f) << "trial " << trial;
        for (int i = 0; i < 200; ++i) {
            const glm::vec4 p = m * glm::vec4(sphere.centre + testing::randomUnit(rng) * sphere.radius, 1.0f);
            const glm::vec2 texel = glm::vec2(p) * size;
            EXPECT_GE(texel.x, low.x - 1e-3f);
            EXPECT_GE(texel.y, low.y - 1e-3f);
            EXPECT_LE(texel.x, high.x + 1e-3f);
            EXPECT_LE(texel.y, high.y + 1e-3f);
            EXPECT_GE(p.z, -1e-5f); // between the near and far planes
            EXPECT_LE(p.z, 1.0f + 1e-5f);
        }
    }
}

TEST(CascadeFit, TheLightViewLooksAlongTheLightDirection)
{
    const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f));
    const DirectionalShadowCascade fit =
        fitDirectionalCascade({{1, 2, 3}, 4.0f}, lightSpaceCasters(lightBasis(direction), {}), 256, 0.0f,
                              defaultConventions);
    const glm::vec4 a = fit.view * glm::vec4(5, 6, 7, 1);
    const glm::vec4 b = fit.view * glm::vec4(glm::vec3(5, 6, 7) + direction, 1);
    EXPECT_NEAR(b.x - a.x, 0.0f, 1e-5f);
    EXPECT_NEAR(b.y - a.y, 0.0f, 1e-5f);
    EXPECT_NEAR(b.z - a.z, -1.0f, 1e-5f);
    EXPECT_NEAR(glm::determinant(glm::mat3(fit.view)), 1.0f, 1e-5f); // a rotation: right-handed
}

TEST(CascadeFit, NearPlaneIsPulledBackOverCastersInTheFootprintAndByTheOffset)
{
    // Light straight down: light depth is -y.
    const LightBasis basis = lightBasis({0.0f, -1.0f, 0.0f});
    const Sphere sphere{{0.0f, 0.0f, 0.0f}, 10.0f};
    const DirectionalShadowCascade plain =
        fitDirectionalCascade(sphere, lightSpaceCasters(basis, {}), 512, 0.0f, defaultConventions);
    EXPECT_NEAR(plain.nearDepth, -10.0f, 1e-5f);
    EXPECT_NEAR(plain.farDepth, 10.0f, 1e-5f);

    const std::vector<Bounds> casters{
        {{-1.0f, 40.0f, -1.0f}, {1.0f, 50.0f, 1.0f}}, // above the sphere, inside the footprint
        {{100.0f, 90.0f, 0.0f}, {101.0f, 95.0f, 1.0f}}, // higher still, but outside the footprint
    };
    const DirectionalShadowCascade pulled =
        fitDirectionalCascade(sphere, lightSpaceCasters(basis, casters), 512, 2.0f, defaultConventions);
    EXPECT_NEAR(pulled.nearDepth, -52.0f, 1e-4f);
    EXPECT_NEAR(pulled.farDepth, 10.0f, 1e-5f);
    // The caster's top is 2 units behind the near plane: window depth in range, not clipped.
    const glm::vec4 top = pulled.viewProjection * glm::vec4(0.0f, 50.0f, 0.0f, 1.0f);
    EXPECT_NEAR(top.z, 2.0f / 62.0f, 1e-5f);
}

// The far plane follows the sphere, so without a grid every camera move would change every depth the tile holds by a
// rounding, and the soft filters' texel-rounded taps with them.
TEST(CascadeFit, DepthPlanesStayPutAsTheCameraMovesWithinAGridStep)
{
    const LightBasis basis = lightBasis(glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f)));
    const auto fitAt = [&](glm::vec3 centre) {
        return fitDirectionalCascade({centre, 10.3f}, lightSpaceCasters(basis, {}), 2048, 0.0f, defaultConventions);
    };
    const DirectionalShadowCascade still = fitAt({1.4f, 2.0f, 0.0f});
    const float grid = depthPlaneGrid(still.texelSize);
    EXPECT_GE(grid, 16.0f * still.texelSize);
    EXPECT_LT(grid, 32.0f * still.texelSize);
    EXPECT_EQ(std::fmod(still.nearDepth, grid), 0.0f);
    EXPECT_EQ(std::fmod(still.farDepth, grid), 0.0f);
    const float centreDepth = basis.toLight({1.4f, 2.0f, 0.0f}).z;
    EXPECT_LE(still.nearDepth, centreDepth - 10.3f);
    EXPECT_GE(still.farDepth, centreDepth + 10.3f);
    EXPECT_LT(still.farDepth - still.nearDepth, 2.0f * 10.3f + 2.0f * grid);
    for (const glm::vec3 step : {glm::vec3(0.004f, 0.0f, 0.0f), glm::vec3(0.0f, 0.003f, 0.007f)}) {
        const DirectionalShadowCascade moved = fitAt(glm::vec3(1.4f, 2.0f, 0.0f) + step);
        EXPECT_EQ(moved.nearDepth, still.nearDepth);
        EXPECT_EQ(moved.farDepth, still.farDepth);
    }
}

// The centre-and-extent transform of a box gives the box of its eight transformed corners.
TEST(CascadeFit, LightSpaceBoundsOfABoxAreThoseOfItsCorners)
{
    const Bounds box{{-3.0f, 0.5f, 2.0f}, {1.0f, 4.0f, 2.5f}};
    for (const glm::vec3 direction :
         {glm::vec3(0.3f, -1.0f, 0.4f), glm::vec3(-0.7f, -0.2f, 0.1f), glm::vec3(0, -1, 0)}) {
        const LightBasis basis = lightBasis(direction);
        const Bounds fast = lightSpaceBounds(basis, box);
        const Bounds corners = lightSpaceBounds(basis, box.corners());
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_NEAR(fast.min[axis], corners.min[axis], 1e-5f) << axis;
            EXPECT_NEAR(fast.max[axis], corners.max[axis], 1e-5f) << axis;
        }
    }
}

} // namespace
} // namespace penumbra::shadows
