#include "penumbra/scene/MeshGenerators.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <stdexcept>

namespace penumbra::scene {
namespace {

std::uint32_t vertexCount(const MeshData& mesh) { return static_cast<std::uint32_t>(mesh.vertices.size()); }

void addTriangle(MeshData& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// Quad a-b-c-d counter-clockwise seen from the side it faces.
void addQuad(MeshData& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d)
{
    addTriangle(mesh, a, b, c);
    addTriangle(mesh, a, c, d);
}

// Point on the unit circle around y at angle `theta` from +z towards +x. With rows going
// down (-y) and columns going towards larger theta, (down, across) is counter-clockwise
// seen from outside: cross(-y, +x) = +z at theta = 0.
glm::vec3 around(float theta) { return {std::sin(theta), 0.0f, std::cos(theta)}; }

float angle(std::uint32_t segment, std::uint32_t segments)
{
    return glm::two_pi<float>() * static_cast<float>(segment) / static_cast<float>(segments);
}

} // namespace

MeshData makeBox(const glm::vec3& halfExtents)
{
    // Each face: outward normal n and "up" direction v within the face; u = cross(v, n)
    // makes (u, v, n) right-handed, so corners (-u-v, +u-v, +u+v, -u+v) run counter-clockwise
    // seen from outside.
    struct Face {
        glm::vec3 n;
        glm::vec3 v;
    };
    constexpr Face faces[] = {
        {{1, 0, 0}, {0, 1, 0}},  {{-1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}},
        {{0, 0, -1}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, -1}}, {{0, -1, 0}, {0, 0, 1}},
    };
    MeshData mesh;
    for (const Face& face : faces) {
        const glm::vec3 u = glm::cross(face.v, face.n);
        const std::uint32_t first = vertexCount(mesh);
        constexpr glm::vec2 signs[] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2& s : signs) {
            const glm::vec3 position = halfExtents * (face.n + s.x * u + s.y * face.v);
            mesh.vertices.push_back({position, face.n, {0.5f + 0.5f * s.x, 0.5f - 0.5f * s.y}});
        }
        addQuad(mesh, first, first + 1, first + 2, first + 3);
    }
    updateBounds(mesh);
    return mesh;
}

MeshData makeSphere(float radius, std::uint32_t segments, std::uint32_t rings)
{
    if (segments < 3 || rings < 2)
        throw std::invalid_argument("makeSphere needs at least 3 segments and 2 rings");
    MeshData mesh;
    // (rings + 1) rows of (segments + 1) vertices: the seam column is duplicated so u reaches 1.
    for (std::uint32_t ring = 0; ring <= rings; ++ring) {
        const float phi = glm::pi<float>() * static_cast<float>(ring) / static_cast<float>(rings);
        for (std::uint32_t segment = 0; segment <= segments; ++segment) {
            const glm::vec3 normal = std::sin(phi) * around(angle(segment, segments)) + glm::vec3(0, std::cos(phi), 0);
            const glm::vec2 uv{static_cast<float>(segment) / static_cast<float>(segments),
                               static_cast<float>(ring) / static_cast<float>(rings)};
            mesh.vertices.push_back({radius * normal, normal, uv});
        }
    }
    const std::uint32_t row = segments + 1;
    for (std::uint32_t ring = 0; ring < rings; ++ring) {
        for (std::uint32_t segment = 0; segment < segments; ++segment) {
            const std::uint32_t a = ring * row + segment;
            const std::uint32_t b = a + row;
            const std::uint32_t c = b + 1;
            const std::uint32_t d = a + 1;
            // At the poles a and d (or b and c) coincide; keep the one non-degenerate half.
            if (ring == 0)
                addTriangle(mesh, a, b, c);
            else if (ring == rings - 1)
                addTriangle(mesh, a, b, d);
            else
                addQuad(mesh, a, b, c, d);
        }
    }
    updateBounds(mesh);
    return mesh;
}

MeshData makeCylinder(float radius, float halfHeight, std::uint32_t segments)
{
    if (segments < 3)
        throw std::invalid_argument("makeCylinder needs at least 3 segments");
    MeshData mesh;
    const glm::vec3 top{0.0f, halfHeight, 0.0f};
    // Side: a top and a bottom row, seam duplicated.
    for (std::uint32_t segment = 0; segment <= segments; ++segment) {
        const glm::vec3 normal = around(angle(segment, segments));
        const float u = static_cast<float>(segment) / static_cast<float>(segments);
        mesh.vertices.push_back({radius * normal + top, normal, {u, 0.0f}});
        mesh.vertices.push_back({radius * normal - top, normal, {u, 1.0f}});
    }
    for (std::uint32_t segment = 0; segment < segments; ++segment) {
        const std::uint32_t a = 2 * segment;
        addQuad(mesh, a, a + 1, a + 3, a + 2);
    }
    // Caps: a centre and a rim each; the rim's uv is a disc inscribed in [0, 1]^2.
    for (const float side : {1.0f, -1.0f}) {
        const glm::vec3 normal{0.0f, side, 0.0f};
        const std::uint32_t centre = vertexCount(mesh);
        mesh.vertices.push_back({side * top, normal, {0.5f, 0.5f}});
        for (std::uint32_t segment = 0; segment <= segments; ++segment) {
            const glm::vec3 direction = around(angle(segment, segments));
            mesh.vertices.push_back(
                {radius * direction + side * top, normal, {0.5f + 0.5f * direction.x, 0.5f + 0.5f * direction.z}});
        }
        // Going towards larger theta is counter-clockwise seen from +y (cross(+z, +x) = +y),
        // clockwise seen from -y.
        for (std::uint32_t segment = 0; segment < segments; ++segment) {
            const std::uint32_t rim = centre + 1 + segment;
            if (side > 0.0f)
                addTriangle(mesh, centre, rim, rim + 1);
            else
                addTriangle(mesh, centre, rim + 1, rim);
        }
    }
    updateBounds(mesh);
    return mesh;
}

MeshData makePlane(float halfSize, std::uint32_t subdivisions)
{
    if (subdivisions < 1)
        throw std::invalid_argument("makePlane needs at least 1 subdivision");
    MeshData mesh;
    const std::uint32_t row = subdivisions + 1;
    for (std::uint32_t i = 0; i <= subdivisions; ++i) { // along x
        for (std::uint32_t k = 0; k <= subdivisions; ++k) { // along z
            const glm::vec2 uv{static_cast<float>(i) / static_cast<float>(subdivisions),
                               static_cast<float>(k) / static_cast<float>(subdivisions)};
            const glm::vec3 position{(2.0f * uv.x - 1.0f) * halfSize, 0.0f, (2.0f * uv.y - 1.0f) * halfSize};
            mesh.vertices.push_back({position, {0.0f, 1.0f, 0.0f}, uv});
        }
    }
    // (+z, +x) is counter-clockwise seen from +y: cross(+z, +x) = +y.
    for (std::uint32_t i = 0; i < subdivisions; ++i) {
        for (std::uint32_t k = 0; k < subdivisions; ++k) {
            const std::uint32_t a = i * row + k;
            addQuad(mesh, a, a + 1, a + row + 1, a + row);
        }
    }
    updateBounds(mesh);
    return mesh;
}

} // namespace penumbra::scene
