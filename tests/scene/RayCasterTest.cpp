#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/truth/RayCaster.hpp"
#include "penumbra/truth/RayTriangle.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <span>

#include <cmath>
#include <random>

namespace penumbra::truth {
namespace {

glm::mat4 at(const glm::vec3& position) { return glm::translate(glm::mat4(1.0f), position); }

// Double-sided by default: seen from either side by both kinds of ray.
scene::Scene singleMeshScene(scene::MeshData mesh, const glm::mat4& transform,
                             scene::Material material = {.doubleSided = true})
{
    scene::Scene scene;
    scene.addObject("only", scene.addMesh(std::move(mesh)), scene.addMaterial(std::move(material)), transform);
    return scene;
}

TEST(RayCasterTest, BoxKnownAnswers)
{
    const RayCaster caster(singleMeshScene(scene::makeBox({1, 1, 1}), at({0, 0, 0})));
    EXPECT_EQ(caster.triangleCount(), 12u);
    const auto front = caster.closestHit({0.3f, -0.2f, -5.0f}, {0, 0, 1});
    ASSERT_TRUE(front);
    EXPECT_FLOAT_EQ(front->distance, 4.0f);
    EXPECT_EQ(front->object, 0u);
    EXPECT_NEAR(glm::dot(front->normal, glm::vec3(0, 0, -1)), 1.0f, 1e-6f);
    // From inside: the far wall, reported with its outward (front-side) normal.
    const auto inside = caster.closestHit({0, 0, 0}, {0, 0, 1});
    ASSERT_TRUE(inside);
    EXPECT_FLOAT_EQ(inside->distance, 1.0f);
    EXPECT_NEAR(glm::dot(inside->normal, glm::vec3(0, 0, 1)), 1.0f, 1e-6f);
    // Direction need not be unit; distances stay in world units.
    const auto scaled = caster.closestHit({0, 5, 0}, {0, -10, 0});
    ASSERT_TRUE(scaled);
    EXPECT_FLOAT_EQ(scaled->distance, 4.0f);
    EXPECT_FALSE(caster.closestHit({0, 5, 0}, {0, -1, 0}, 3.9f));
    EXPECT_FALSE(caster.occluded({3, 0, 0}, {0, 1, 0}));
    EXPECT_TRUE(caster.occluded({3, 0.5f, 0.5f}, {-1, 0, 0}));
}

TEST(RayCasterTest, SphereKnownAnswerWithinTessellation)
{
    constexpr float radius = 2.0f;
    constexpr std::uint32_t segments = 64;
    const RayCaster caster(singleMeshScene(scene::makeSphere(radius, segments, 32), at({3, 1, 0})));
    // The inscribed polyhedron lies between r cos(pi / segments)^2 and r from the centre.
    const float tolerance = radius * (1.0f - std::pow(std::cos(glm::pi<float>() / segments), 2.0f));
    for (const glm::vec3& direction : {glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, 2, 3))}) {
        const glm::vec3 origin = glm::vec3(3, 1, 0) - 10.0f * direction;
        const auto hit = caster.closestHit(origin, direction);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->distance, 10.0f - radius, tolerance);
        EXPECT_GT(glm::dot(hit->normal, -direction), 0.9f);
    }
    EXPECT_FALSE(caster.closestHit({3, 3.5f, -10}, {0, 0, 1})); // passes above
}

TEST(RayCasterTest, TriangleIndexAndBarycentricsReferToTheMesh)
{
    const scene::Scene scene = singleMeshScene(scene::makePlane(1.0f), at({0, 2, 0}));
    const RayCaster caster(scene);
    const glm::vec3 origin{0.3f, 5.0f, -0.4f};
    const auto hit = caster.closestHit(origin, {0, -1, 0});
    ASSERT_TRUE(hit);
    const scene::MeshData& mesh = scene.meshes[0];
    const glm::vec3 p0 = mesh.vertices[mesh.indices[3 * hit->triangle]].position;
    const glm::vec3 p1 = mesh.vertices[mesh.indices[3 * hit->triangle + 1]].position;
    const glm::vec3 p2 = mesh.vertices[mesh.indices[3 * hit->triangle + 2]].position;
    const glm::vec3 local =
        (1.0f - hit->barycentrics.x - hit->barycentrics.y) * p0 + hit->barycentrics.x * p1 + hit->barycentrics.y * p2;
    EXPECT_NEAR(glm::length(local - glm::vec3(0.3f, 0.0f, -0.4f)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(hit->normal, glm::vec3(0, 1, 0)), 1.0f, 1e-6f);
}

// The test scene with every material made a solid double-sided caster, so brute force needs no alpha nor culling.
scene::Scene solidTestScene()
{
    scene::Scene scene = scenes::makeShadowTestScene();
    for (scene::Material& material : scene.materials) {
        material.caster = scene::CasterMode::On;
        material.doubleSided = true;
    }
    return scene;
}

// A triangle of the scene in world space.
struct WorldTriangle {
    std::uint32_t object;
    std::uint32_t triangle;
    glm::vec3 v[3];
};

// Every triangle of the scene, transformed once for all the rays.
std::vector<WorldTriangle> worldTriangles(const scene::Scene& scene)
{
    std::vector<WorldTriangle> triangles;
    for (std::uint32_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& object = scene.objects[o];
        const scene::MeshData& mesh = scene.meshOf(object);
        for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
            WorldTriangle& world = triangles.emplace_back(WorldTriangle{o, t, {}});
            for (std::uint32_t k = 0; k < 3; ++k)
                world.v[k] =
                    glm::vec3(object.transform * glm::vec4(mesh.vertices[mesh.indices[3 * t + k]].position, 1.0f));
        }
    }
    return triangles;
}

std::optional<Hit> bruteForceClosest(std::span<const WorldTriangle> triangles, const glm::vec3& origin,
                                     const glm::vec3& direction)
{
    std::optional<Hit> best;
    for (const WorldTriangle& t : triangles) {
        const auto hit = intersectRayTriangle(origin, direction, t.v[0], t.v[1], t.v[2],
                                              best ? best->distance : std::numeric_limits<float>::infinity());
        if (hit)
            best = Hit{hit->distance, t.object, t.triangle, hit->barycentrics,
                       glm::normalize(glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0]))};
    }
    return best;
}

TEST(RayCasterTest, BvhAgreesWithBruteForceOnRandomRays)
{
    const scene::Scene scene = solidTestScene();
    const RayCaster caster(scene);
    const std::vector<WorldTriangle> triangles = worldTriangles(scene);
    std::mt19937 random(1234);
    std::uniform_real_distribution<float> position(-12.0f, 12.0f);
    std::uniform_real_distribution<float> height(0.01f, 8.0f);
    std::normal_distribution<float> gaussian;
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 origin{position(random), height(random), position(random)};
        const glm::vec3 direction = glm::normalize(glm::vec3(gaussian(random), gaussian(random), gaussian(random)));
        const float maxDistance = (i % 4 == 0) ? 5.0f : std::numeric_limits<float>::infinity();
        const auto expected = bruteForceClosest(triangles, origin, direction);
        const bool expectedHit = expected && expected->distance <= maxDistance;
        const auto actual = caster.closestHit(origin, direction, maxDistance);
        ASSERT_EQ(actual.has_value(), expectedHit) << "ray " << i;
        ASSERT_EQ(caster.occluded(origin, direction, maxDistance), expectedHit) << "ray " << i;
        if (!expectedHit)
            continue;
        ++hits;
        ASSERT_NEAR(actual->distance, expected->distance, 1e-4f * (1.0f + expected->distance)) << "ray " << i;
        // Ties (shared edges, coincident faces) may pick either triangle; distances must agree.
        if (actual->object != expected->object || actual->triangle != expected->triangle) {
            ASSERT_NEAR(actual->distance, expected->distance, 1e-5f) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 500);
}

TEST(RayCasterTest, FloatingBoxShadowsThePointBelowForAVerticalLight)
{
    scene::Scene scene;
    const std::uint32_t plain = scene.addMaterial({});
    scene.addObject("ground", scene.addMesh(scene::makePlane(20.0f)), plain, glm::mat4(1.0f));
    scene.addObject("box", scene.addMesh(scene::makeBox({1, 1, 1})), plain, at({2, 3, -1}));
    const RayCaster caster(scene);
    const glm::vec3 towardsLight{0, 1, 0};
    constexpr float offset = 1e-3f;
    EXPECT_TRUE(caster.occluded({2, offset, -1}, towardsLight));
    EXPECT_TRUE(caster.occluded({2.9f, offset, -0.1f}, towardsLight));
    EXPECT_FALSE(caster.occluded({3.1f, offset, -1}, towardsLight));
    EXPECT_FALSE(caster.occluded({10, offset, 10}, towardsLight));
    EXPECT_FALSE(caster.occluded({2, offset, -1}, towardsLight, 1.9f)); // the box starts at height 2
}

// A 3 x 3 Clip panel at y = 2 over the origin: 5 x 5 checker cells of 0.6, the cell at
// (-x, -z) solid, its +x neighbour a hole.
scene::Scene panelScene(scene::CasterMode mode, float alpha)
{
    scene::Scene scene;
    scene.addObject("panel", scene.addMesh(scene::makeBox({1.5f, 0.05f, 1.5f})),
                    scene.addMaterial({.baseColor = {1, 1, 1, alpha}, .caster = mode}), at({0, 2, 0}));
    return scene;
}

TEST(RayCasterTest, ClipCastersHaveCheckerHolesForShadowAndCameraRays)
{
    const scene::Scene scene = panelScene(scene::CasterMode::Clip, 1.0f);
    const glm::vec3 solidCell{-1.2f, 0, -1.2f}, holeCell{-0.6f, 0, -1.2f};
    for (const RayKind kind : {RayKind::Shadow, RayKind::Camera}) {
        const RayCaster caster(scene, kind);
        EXPECT_TRUE(caster.occluded(solidCell, {0, 1, 0}));
        EXPECT_FALSE(caster.occluded(holeCell, {0, 1, 0}));
        EXPECT_FALSE(caster.closestHit(holeCell, {0, 1, 0}));
        EXPECT_TRUE(caster.closestHit(solidCell, {0, 1, 0}));
    }
    // Alpha below the cutoff everywhere: no caster at all.
    EXPECT_FALSE(RayCaster(panelScene(scene::CasterMode::Clip, 0.4f)).occluded(solidCell, {0, 1, 0}));
}

TEST(RayCasterTest, DitherCastersThresholdAlphaAtOneHalfForShadowsOnly)
{
    const glm::vec3 below{-0.6f, 0, -1.2f};
    EXPECT_TRUE(RayCaster(panelScene(scene::CasterMode::Dither, 0.6f)).occluded(below, {0, 1, 0}));
    EXPECT_FALSE(RayCaster(panelScene(scene::CasterMode::Dither, 0.4f)).occluded(below, {0, 1, 0}));
    EXPECT_TRUE(RayCaster(panelScene(scene::CasterMode::Dither, 0.4f), RayKind::Camera).occluded(below, {0, 1, 0}));
}

TEST(RayCasterTest, DitheredCastersAreReportedApartWithTheirLargestAlpha)
{
    const glm::vec3 below{-0.6f, 0, -1.2f};
    const Occlusion dithered = RayCaster(panelScene(scene::CasterMode::Dither, 0.3f)).occlusion(below, {0, 1, 0});
    EXPECT_FALSE(dithered.solid);
    EXPECT_FLOAT_EQ(dithered.ditherCoverage, 0.3f);
    scene::Scene layered = panelScene(scene::CasterMode::Dither, 0.3f);
    layered.addObject("upper panel", layered.addMesh(scene::makeBox({1.5f, 0.05f, 1.5f})),
                      layered.addMaterial({.baseColor = {1, 1, 1, 0.7f}, .caster = scene::CasterMode::Dither}),
                      at({0, 4, 0}));
    EXPECT_FLOAT_EQ(RayCaster(layered).occlusion(below, {0, 1, 0}).ditherCoverage, 0.7f);
    layered.addObject("roof", layered.addMesh(scene::makeBox({1.5f, 0.05f, 1.5f})), layered.addMaterial({}),
                      at({0, 6, 0}));
    EXPECT_TRUE(RayCaster(layered).occlusion(below, {0, 1, 0}).solid);
    const Occlusion open = RayCaster(layered).occlusion({10, 0, 0}, {0, 1, 0});
    EXPECT_FALSE(open.solid);
    EXPECT_EQ(open.ditherCoverage, 0.0f);
}

// The passes' culling: the lit pass draws the front of single-sided materials, the shadow pass the light-facing
// side of single-sided casters (a shadow ray leaves through it), both sides of double-sided materials and of
// two-sided casters.
TEST(RayCasterTest, SingleSidedSurfacesAreSeenFromTheSideThePassesDraw)
{
    const glm::vec3 above{0.3f, 5, -0.4f}, below{0.3f, -5, -0.4f};
    const glm::vec3 up{0, 1, 0}, down{0, -1, 0};
    scene::Scene scene = singleMeshScene(scene::makePlane(1.0f), glm::mat4(1.0f), {}); // faces +y
    EXPECT_TRUE(RayCaster(scene, RayKind::Camera).occluded(above, down));
    EXPECT_FALSE(RayCaster(scene, RayKind::Camera).occluded(below, up));
    EXPECT_TRUE(RayCaster(scene).occluded(below, up)); // light above: the front faces it
    EXPECT_FALSE(RayCaster(scene).occluded(above, down)); // light below: the front faces away
    scene.objects[0].castShadows = scene::ShadowCasting::TwoSided;
    EXPECT_TRUE(RayCaster(scene).occluded(above, down));
    EXPECT_FALSE(RayCaster(scene, RayKind::Camera).occluded(below, up));
    scene.materials[0].doubleSided = true;
    scene.objects[0].castShadows = scene::ShadowCasting::On;
    EXPECT_TRUE(RayCaster(scene).occluded(above, down));
    EXPECT_TRUE(RayCaster(scene, RayKind::Camera).occluded(below, up));
    // A closed single-sided mesh blocks from every side.
    const RayCaster box(singleMeshScene(scene::makeBox({1, 1, 1}), glm::mat4(1.0f), {}));
    EXPECT_TRUE(box.occluded(below, up));
    EXPECT_TRUE(box.occluded(above, down));
    EXPECT_FLOAT_EQ(box.closestHit(below, up)->distance, 6.0f); // through the culled bottom, to the top
}

TEST(RayCasterTest, OffCastersAreOnlySeenByTheCamera)
{
    const scene::Scene scene = panelScene(scene::CasterMode::Off, 1.0f);
    EXPECT_EQ(RayCaster(scene).triangleCount(), 0u);
    EXPECT_FALSE(RayCaster(scene).occluded({-1.2f, 0, -1.2f}, {0, 1, 0}));
    EXPECT_FALSE(RayCaster(scene).closestHit({-1.2f, 0, -1.2f}, {0, 1, 0}));
    EXPECT_TRUE(RayCaster(scene, RayKind::Camera).occluded({-1.2f, 0, -1.2f}, {0, 1, 0}));
}

TEST(RayCasterTest, InvalidSceneIsRejected)
{
    scene::Scene scene = panelScene(scene::CasterMode::On, 1.0f);
    scene.objects[0].material = 9;
    EXPECT_THROW(RayCaster{scene}, scene::SceneError);
}

} // namespace
} // namespace penumbra::truth
