// Clustered light lists against a brute-force reference: every light that reaches a point is in its cluster's list.
#include "ShadowTestSupport.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/LightClusters.hpp"

#include <chrono>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <random>

namespace penumbra::shadows {
namespace {

ShadowCamera longStreetCamera()
{
    return {.position = {0.0f, 1.7f, 150.0f},
            .forward = {0.0f, 0.0f, -1.0f},
            .up = {0.0f, 1.0f, 0.0f},
            .fovY = glm::radians(60.0f),
            .aspect = 16.0f / 9.0f,
            .nearPlane = 0.1f,
            .farPlane = 400.0f};
}

// `count` lights in a 60 x 12 x 320 box ahead of and around the camera, spot lights (every other one) pointing in
// random directions, ranges 2 to 15.
std::vector<ClusterLight> randomLights(std::mt19937& rng, std::size_t count)
{
    std::uniform_real_distribution<float> x(-30.0f, 30.0f);
    std::uniform_real_distribution<float> y(-1.0f, 11.0f);
    std::uniform_real_distribution<float> z(-170.0f, 170.0f);
    std::uniform_real_distribution<float> range(2.0f, 15.0f);
    std::uniform_real_distribution<float> angle(0.1f, 1.5f);
    std::vector<ClusterLight> lights;
    for (std::size_t i = 0; i < count; ++i) {
        ClusterLight light{.position = {x(rng), y(rng), z(rng)}, .range = range(rng)};
        if (i % 2 == 1) {
            light.kind = LightKind::Spot;
            light.direction = testing::randomUnit(rng);
            light.outerAngle = angle(rng);
        }
        lights.push_back(light);
    }
    return lights;
}

// Random points in the view frustum, half of them on the lights (inside their reach), where misses would show.
std::vector<glm::vec3> framePoints(std::mt19937& rng, const ShadowCamera& camera, std::span<const ClusterLight> lights,
                                   std::size_t count)
{
    const glm::vec3 right = glm::cross(camera.forward, camera.up);
    const float t = std::tan(0.5f * camera.fovY);
    std::uniform_real_distribution<float> ndc(-1.0f, 1.0f);
    std::uniform_real_distribution<float> depthFraction(0.0f, 1.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_int_distribution<std::size_t> pick(0, lights.size() - 1);
    std::vector<glm::vec3> points;
    while (points.size() < count) {
        if (points.size() % 2 == 0) {
            // Depth spread exponentially, as the slices are.
            const float depth = camera.nearPlane * std::pow(camera.farPlane / camera.nearPlane, depthFraction(rng));
            points.push_back(camera.position + depth * (camera.forward + ndc(rng) * camera.aspect * t * right +
                                                        ndc(rng) * t * camera.up));
            continue;
        }
        const ClusterLight& light = lights[pick(rng)];
        const glm::vec3 p = light.position + testing::randomUnit(rng) * light.range * std::cbrt(unit(rng));
        if (lightReaches(light, p) &&
            clusterAt(camera, LightClusterUniforms{.nearPlane = camera.nearPlane, .farPlane = camera.farPlane}, p))
            points.push_back(p);
    }
    return points;
}

// The lights that reach each point and are missing from its cluster's list.
std::size_t countMisses(const LightClusters& clusters, const ShadowCamera& camera, std::span<const ClusterLight> lights,
                        std::span<const glm::vec3> points)
{
    std::size_t misses = 0;
    for (const glm::vec3& p : points) {
        const std::optional<std::uint32_t> cluster = clusterAt(camera, clusters.grid, p);
        if (!cluster)
            continue;
        const LightClusterRange range = clusters.ranges[*cluster];
        const auto first = clusters.lightIndices.begin() + range.offset;
        for (std::uint32_t i = 0; i < lights.size(); ++i)
            if (lightReaches(lights[i], p) && !std::binary_search(first, first + range.count, i))
                ++misses;
    }
    return misses;
}

TEST(LightClusters, EveryLightThatReachesAPointIsInItsClusterList)
{
    std::mt19937 rng(11);
    const ShadowCamera camera = longStreetCamera();
    const std::vector<ClusterLight> lights = randomLights(rng, 1024);
    const auto start = std::chrono::steady_clock::now();
    const LightClusters clusters = buildLightClusters(camera, lights);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const std::vector<glm::vec3> points = framePoints(rng, camera, lights, 20'000);
    EXPECT_EQ(countMisses(clusters, camera, lights, points), 0u);
    // Lists follow the lights: far fewer entries than every light in every cluster.
    ASSERT_EQ(clusters.ranges.size(), std::size_t(16) * 9 * 24);
    const double perCluster = double(clusters.lightIndices.size()) / double(clusters.ranges.size());
    EXPECT_LT(perCluster, 0.05 * double(lights.size()));
    RecordProperty("buildMs", std::to_string(ms));
    std::printf("1024 lights: %.2f ms, %.1f lights per cluster on average\n", ms, perCluster);
}

TEST(LightClusters, ListsAreConsecutiveAndAscending)
{
    std::mt19937 rng(5);
    const std::vector<ClusterLight> lights = randomLights(rng, 200);
    const LightClusters clusters =
        buildLightClusters(longStreetCamera(), lights, {.tilesX = 8, .tilesY = 4, .slices = 6});
    ASSERT_EQ(clusters.ranges.size(), 8u * 4 * 6);
    std::uint32_t next = 0;
    for (const LightClusterRange& r : clusters.ranges) {
        EXPECT_EQ(r.offset, next);
        next += r.count;
        EXPECT_TRUE(std::is_sorted(clusters.lightIndices.begin() + r.offset,
                                   clusters.lightIndices.begin() + r.offset + r.count));
    }
    EXPECT_EQ(next, clusters.lightIndices.size());
    EXPECT_EQ(clusters.grid.indexCount, next);
}

TEST(LightClusters, LookupMatchesTheGridsFormula)
{
    const ShadowCamera camera = longStreetCamera();
    const LightClusters clusters = buildLightClusters(camera, {});
    const LightClusterUniforms& g = clusters.grid;
    // The top-left corner, just past the near plane, is cluster 0; the bottom-right at the far plane the last.
    EXPECT_EQ(clusterIndex(g, {-0.999f, 0.999f}, 0.1001f), 0u);
    EXPECT_EQ(clusterIndex(g, {0.999f, -0.999f}, 399.0f), 16u * 9 * 24 - 1);
    // Tile y counts from the top: NDC y = 1 is row 0.
    EXPECT_EQ(clusterIndex(g, {-0.999f, -0.999f}, 0.1001f), 16u * 8);
    // Slice k begins at near x (far / near)^(k / slices).
    const float start = camera.nearPlane * std::pow(camera.farPlane / camera.nearPlane, 10.0f / 24.0f);
    EXPECT_EQ(clusterIndex(g, {-0.999f, 0.999f}, start * 1.001f), 16u * 9 * 10);
    EXPECT_EQ(clusterIndex(g, {-0.999f, 0.999f}, start * 0.999f), 16u * 9 * 9);
}

TEST(LightClusters, SpotConesSkipClustersBesideThem)
{
    const ShadowCamera camera = longStreetCamera();
    // A narrow spot light pointing down ahead of the camera, and a point light of the same range there.
    const ClusterLight spot{.kind = LightKind::Spot,
                            .position = {0.0f, 6.0f, 120.0f},
                            .range = 10.0f,
                            .direction = {0.0f, -1.0f, 0.0f},
                            .outerAngle = 0.3f};
    ClusterLight point = spot;
    point.kind = LightKind::Point;
    const LightClusters spotClusters = buildLightClusters(camera, std::vector<ClusterLight>{spot});
    const LightClusters pointClusters = buildLightClusters(camera, std::vector<ClusterLight>{point});
    EXPECT_GT(spotClusters.lightIndices.size(), 0u);
    EXPECT_LT(2 * spotClusters.lightIndices.size(), pointClusters.lightIndices.size());
}

TEST(LightClusters, MissCountCatchesFault)
{
    // Lists built for lights half their range miss the points the full lights reach.
    std::mt19937 rng(2);
    const ShadowCamera camera = longStreetCamera();
    const std::vector<ClusterLight> lights = randomLights(rng, 64);
    std::vector<ClusterLight> shrunk = lights;
    for (ClusterLight& light : shrunk)
        light.range *= 0.5f;
    const LightClusters clusters = buildLightClusters(camera, shrunk);
    EXPECT_GT(countMisses(clusters, camera, lights, framePoints(rng, camera, lights, 2000)), 0u);
}

TEST(LightClusters, RejectsBadGridsCamerasAndLights)
{
    const ShadowCamera camera = longStreetCamera();
    EXPECT_THROW(buildLightClusters(camera, {}, {.tilesX = 0}), rhi::Error);
    EXPECT_THROW(buildLightClusters(camera, {}, {.slices = 1000}), rhi::Error);
    ShadowCamera flat = camera;
    flat.farPlane = flat.nearPlane;
    EXPECT_THROW(buildLightClusters(flat, {}), rhi::Error);
    EXPECT_THROW(buildLightClusters(camera, std::vector<ClusterLight>{{.range = 0.0f}}), rhi::Error);
    EXPECT_THROW(buildLightClusters(camera, std::vector<ClusterLight>{{.kind = LightKind::Spot, .outerAngle = 1.6f}}),
                 rhi::Error);
}

} // namespace
} // namespace penumbra::shadows
