#include "penumbra/scene/Geometry.hpp"

#include <glm/common.hpp>
#include <glm/vec4.hpp>

namespace penumbra::scene {

void Bounds::extend(const glm::vec3& point)
{
    min = glm::min(min, point);
    max = glm::max(max, point);
}

void Bounds::extend(const Bounds& other)
{
    min = glm::min(min, other.min);
    max = glm::max(max, other.max);
}

Bounds Bounds::merged(const Bounds& other) const
{
    Bounds result = *this;
    result.extend(other);
    return result;
}

bool Bounds::contains(const glm::vec3& point, float tolerance) const
{
    return glm::all(glm::greaterThanEqual(point, min - tolerance)) &&
           glm::all(glm::lessThanEqual(point, max + tolerance));
}

std::array<glm::vec3, 8> Bounds::corners() const
{
    std::array<glm::vec3, 8> result;
    for (std::size_t i = 0; i < result.size(); ++i)
        result[i] = {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    return result;
}

Bounds Bounds::transformed(const glm::mat4& transform) const
{
    if (empty())
        return {};
    Bounds result;
    for (const glm::vec3& corner : corners())
        result.extend(glm::vec3(transform * glm::vec4(corner, 1.0f)));
    return result;
}

void updateBounds(MeshData& mesh)
{
    mesh.bounds = {};
    for (const Vertex& vertex : mesh.vertices)
        mesh.bounds.extend(vertex.position);
}

} // namespace penumbra::scene
