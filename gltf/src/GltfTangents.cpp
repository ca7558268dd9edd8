#include "GltfTangents.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace penumbra::gltf {
namespace {

// Below this |du1 dv2 - du2 dv1| a triangle's uvs span no area: it gives no tangent direction.
constexpr float kDegenerateUvArea = 1e-12f;

glm::vec2 uvOf(const scene::Vertex& vertex, std::uint32_t texCoord) { return texCoord == 0 ? vertex.uv : vertex.uv1; }

// Any unit vector perpendicular to n, for vertices whose triangles have no uv area.
glm::vec3 perpendicular(const glm::vec3& n)
{
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(axis, n));
}

} // namespace

void computeTangents(scene::MeshData& mesh, std::uint32_t texCoord)
{
    std::vector<glm::vec3> tangents(mesh.vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> bitangents(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        const scene::Vertex &a = mesh.vertices[i0], &b = mesh.vertices[i1], &c = mesh.vertices[i2];
        const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
        const glm::vec2 d1 = uvOf(b, texCoord) - uvOf(a, texCoord), d2 = uvOf(c, texCoord) - uvOf(a, texCoord);
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < kDegenerateUvArea)
            continue;
        // dP/du and dP/dv scaled by twice the triangle's uv area (the sign of det cancels), so larger
        // triangles weigh more.
        const float sign = det > 0.0f ? 1.0f : -1.0f;
        const glm::vec3 dPdu = sign * (e1 * d2.y - e2 * d1.y);
        // glTF's v runs down the image while a normal texture's +Y points up it (section 3.9.3): the
        // bitangent is -dP/dv.
        const glm::vec3 up = -sign * (e2 * d1.x - e1 * d2.x);
        for (const std::uint32_t i : {i0, i1, i2}) {
            tangents[i] += dPdu;
            bitangents[i] += up;
        }
    }
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        scene::Vertex& vertex = mesh.vertices[i];
        const glm::vec3 n = glm::normalize(vertex.normal);
        const glm::vec3 projected = tangents[i] - n * glm::dot(n, tangents[i]);
        const float length = glm::length(projected);
        const glm::vec3 t = length > 0.0f ? projected / length : perpendicular(n);
        const float w = glm::dot(glm::cross(n, t), bitangents[i]) < 0.0f ? -1.0f : 1.0f;
        vertex.tangent = glm::vec4(t, w);
    }
}

} // namespace penumbra::gltf
