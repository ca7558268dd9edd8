#include "penumbra/shadows/LightBasis.hpp"

#include <cmath>
#include <glm/common.hpp>

namespace penumbra::shadows {

LightBasis lightBasis(glm::vec3 direction)
{
    const glm::vec3 d = glm::normalize(direction);
    // World +y as the reference up, or +z for lights (nearly) straight up or down.
    const glm::vec3 reference = std::abs(d.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 right = glm::normalize(glm::cross(d, reference));
    return {right, glm::cross(right, d), d};
}

Bounds lightSpaceBounds(const LightBasis& basis, const std::array<glm::vec3, 8>& corners)
{
    Bounds light{basis.toLight(corners[0]), basis.toLight(corners[0])};
    for (const glm::vec3& corner : corners) {
        const glm::vec3 p = basis.toLight(corner);
        light.min = glm::min(light.min, p);
        light.max = glm::max(light.max, p);
    }
    return light;
}

Bounds lightSpaceBounds(const LightBasis& basis, const Bounds& world)
{
    return lightSpaceBounds(basis, world.corners());
}

} // namespace penumbra::shadows
