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
    LightSpaceCasters casters{basis, world, {}, {}, std::numeric_limits<float>::max()};
    casters.light.reserve(world.size());
    for (const Bounds& box : world)
        casters.light.push_back(lightSpaceBounds(basis, box));
    refitChunks(casters, 0, world.size());
    refitTop(casters);
    return casters;
}

void refitChunks(LightSpaceCasters& casters, std::size_t first, std::size_t end)
{
    const std::size_t count = casters.light.size();
    casters.chunks.resize((count + kLightSpaceChunk - 1) / kLightSpaceChunk);
    for (std::size_t chunk = first / kLightSpaceChunk; chunk < (end + kLightSpaceChunk - 1) / kLightSpaceChunk;
         ++chunk) {
        Bounds box{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
        for (std::size_t i = chunk * kLightSpaceChunk; i < std::min(count, (chunk + 1) * kLightSpaceChunk); ++i) {
            box.min = glm::min(box.min, casters.light[i].min);
            box.max = glm::max(box.max, casters.light[i].max);
        }
        casters.chunks[chunk] = box;
    }
}

void refitTop(LightSpaceCasters& casters)
{
    casters.top = std::numeric_limits<float>::max();
    for (const Bounds& chunk : casters.chunks)
        casters.top = std::min(casters.top, chunk.min.z);
}

float nearestDepthOver(const LightSpaceCasters& casters, glm::vec2 centre, float halfSize, float start)
{
    const auto overlaps = [&](const Bounds& b) {
        return b.max.x >= centre.x - halfSize && b.min.x <= centre.x + halfSize && b.max.y >= centre.y - halfSize &&
               b.min.y <= centre.y + halfSize;
    };
    const auto inside = [&](const Bounds& b) {
        return b.min.x >= centre.x - halfSize && b.max.x <= centre.x + halfSize && b.min.y >= centre.y - halfSize &&
               b.max.y <= centre.y + halfSize;
    };
    float nearest = start;
    for (std::size_t chunk = 0; chunk < casters.chunks.size(); ++chunk) {
        const Bounds& box = casters.chunks[chunk];
        // The chunk's least depth is one of its boxes' min.z, so the minimum taken here is a box's own number.
        if (box.min.z >= nearest || !overlaps(box))
            continue;
        if (inside(box)) {
            nearest = box.min.z;
            continue;
        }
        const std::size_t end = std::min(casters.light.size(), (chunk + 1) * kLightSpaceChunk);
        for (std::size_t i = chunk * kLightSpaceChunk; i < end; ++i)
            if (overlaps(casters.light[i]))
                nearest = std::min(nearest, casters.light[i].min.z);
    }
    return nearest;
}

} // namespace penumbra::shadows
