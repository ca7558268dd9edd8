#include "penumbra/scene/MeshGenerators.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace penumbra::scene {
namespace {

struct Case {
    std::string name;
    MeshData mesh;
    bool closed;
    double volume; // of the tessellated solid when closed, exactly or within relativeTolerance
    double relativeTolerance;
    Bounds bounds;
};

std::vector<Case> cases()
{
    constexpr double pi = glm::pi<double>();
    constexpr std::uint32_t segments = 64;
    // A prism over a regular n-gon inscribed in radius r has area n/2 r^2 sin(2 pi / n).
    const double polygon = 0.5 * segments * std::sin(2.0 * pi / segments);
    return {
        {"box", makeBox({1.0f, 2.0f, 0.5f}), true, 8.0 * 1.0 * 2.0 * 0.5, 1e-6, {{-1, -2, -0.5f}, {1, 2, 0.5f}}},
        {"sphere",
         makeSphere(1.5f, segments, 32),
         true,
         4.0 / 3.0 * pi * 1.5 * 1.5 * 1.5,
         0.01,
         {{-1.5f, -1.5f, -1.5f}, {1.5f, 1.5f, 1.5f}}},
        // Poles and an equator triangle at theta 0, 120 and 240 degrees.
        {"coarse sphere", makeSphere(1.0f, 3, 2), true, 0.0, 1.0, {{-0.8660254f, -1, -0.5f}, {0.8660254f, 1, 1}}},
        {"cylinder",
         makeCylinder(0.5f, 2.0f, segments),
         true,
         polygon * 0.25 * 4.0,
         1e-5,
         {{-0.5f, -2, -0.5f}, {0.5f, 2, 0.5f}}},
        {"plane", makePlane(30.0f), false, 0.0, 0.0, {{-30, 0, -30}, {30, 0, 30}}},
        {"subdivided plane", makePlane(2.0f, 8), false, 0.0, 0.0, {{-2, 0, -2}, {2, 0, 2}}},
    };
}

glm::vec3 position(const MeshData& mesh, std::uint32_t triangle, int corner)
{
    return mesh.vertices[mesh.indices[3 * triangle + static_cast<std::uint32_t>(corner)]].position;
}

TEST(MeshGeneratorsTest, CounterClockwiseFacesAgreeWithVertexNormals)
{
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        ASSERT_EQ(c.mesh.indices.size() % 3, 0u);
        for (std::uint32_t t = 0; t < c.mesh.triangleCount(); ++t) {
            const glm::vec3 geometric = glm::cross(position(c.mesh, t, 1) - position(c.mesh, t, 0),
                                                   position(c.mesh, t, 2) - position(c.mesh, t, 0));
            ASSERT_GT(glm::length(geometric), 1e-7f) << "degenerate triangle " << t;
            for (int k = 0; k < 3; ++k) {
                const Vertex& v = c.mesh.vertices[c.mesh.indices[3 * t + static_cast<std::uint32_t>(k)]];
                ASSERT_GT(glm::dot(glm::normalize(geometric), v.normal), 0.0f) << "triangle " << t << " corner " << k;
                ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
            }
        }
    }
}

TEST(MeshGeneratorsTest, ClosedMeshesEncloseTheirVolume)
{
    for (const Case& c : cases()) {
        if (!c.closed)
            continue;
        SCOPED_TRACE(c.name);
        // Divergence theorem: sum of signed tetrahedra to the origin; positive only when
        // every face is counter-clockwise seen from outside.
        double volume = 0.0;
        for (std::uint32_t t = 0; t < c.mesh.triangleCount(); ++t) {
            const glm::dvec3 a = position(c.mesh, t, 0), b = position(c.mesh, t, 1), d = position(c.mesh, t, 2);
            volume += glm::dot(a, glm::cross(b, d)) / 6.0;
        }
        EXPECT_GT(volume, 0.0);
        if (c.volume > 0.0) {
            EXPECT_NEAR(volume, c.volume, c.volume * c.relativeTolerance);
        }
    }
}

TEST(MeshGeneratorsTest, BoundsAreTheVertexBoxAndTheShapesExtent)
{
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        EXPECT_NEAR(glm::length(c.mesh.bounds.min - c.bounds.min), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(c.mesh.bounds.max - c.bounds.max), 0.0f, 1e-5f);
        for (const Vertex& v : c.mesh.vertices)
            EXPECT_TRUE(c.mesh.bounds.contains(v.position));
    }
}

TEST(MeshGeneratorsTest, SphereAndCylinderReachTheirLowestPointExactly)
{
    // Standing objects touch the floor only if the mesh's lowest point is exactly -extent.
    EXPECT_EQ(makeSphere(0.75f, 48, 24).bounds.min.y, -0.75f);
    EXPECT_EQ(makeCylinder(0.5f, 1.5f, 48).bounds.min.y, -1.5f);
    EXPECT_EQ(makeBox({1, 0.75f, 1}).bounds.min.y, -0.75f);
}

TEST(MeshGeneratorsTest, UvsStayInTheUnitSquare)
{
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        for (const Vertex& v : c.mesh.vertices) {
            EXPECT_GE(v.uv.x, 0.0f);
            EXPECT_LE(v.uv.x, 1.0f);
            EXPECT_GE(v.uv.y, 0.0f);
            EXPECT_LE(v.uv.y, 1.0f);
        }
    }
}

TEST(MeshGeneratorsTest, PlaneFacesUpWithTheRequestedGrid)
{
    const MeshData plane = makePlane(1.0f, 3);
    EXPECT_EQ(plane.vertices.size(), 16u);
    EXPECT_EQ(plane.triangleCount(), 18u);
    for (const Vertex& v : plane.vertices)
        EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
}

TEST(MeshGeneratorsTest, RejectsTooCoarseTessellation)
{
    EXPECT_THROW(makeSphere(1.0f, 2, 8), std::invalid_argument);
    EXPECT_THROW(makeSphere(1.0f, 8, 1), std::invalid_argument);
    EXPECT_THROW(makeCylinder(1.0f, 1.0f, 2), std::invalid_argument);
    EXPECT_THROW(makePlane(1.0f, 0), std::invalid_argument);
}

} // namespace
} // namespace penumbra::scene
