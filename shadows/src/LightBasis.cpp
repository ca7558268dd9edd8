#include "penumbra/shadows/LightBasis.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

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

// The corners' box from the centre and half extents: a linear map M moves the centre to M c, and its corners reach
// |M| e around it along each axis (Arvo, "Transforming Axis-Aligned Bounding Boxes", Graphics Gems, 1990). A
// fifth of transforming the eight corners, which matters to planning, which asks for every caster in every cascade.
Bounds lightSpaceBounds(const LightBasis& basis, const Bounds& world)
{
    const glm::vec3 centre = basis.toLight(0.5f * (world.min + world.max));
    const glm::vec3 half = 0.5f * (world.max - world.min);
    const glm::vec3 reach{glm::dot(glm::abs(basis.right), half), glm::dot(glm::abs(basis.up), half),
                          glm::dot(glm::abs(basis.direction), half)};
    return {centre - reach, centre + reach};
}

LightSpaceCasters lightSpaceCasters(const LightBasis& basis, std::span<const Bounds> world)
{
    LightSpaceCasters casters{basis, world, {}, std::numeric_limits<float>::max()};
    casters.light.reserve(world.size());
    for (const Bounds& box : world) {
        casters.light.push_back(lightSpaceBounds(basis, box));
        casters.top = std::min(casters.top, casters.light.back().min.z);
    }
    return casters;
}

} // namespace penumbra::shadows
