#include "penumbra/shadows/SoftShadowMath.hpp"

#include "penumbra/shadows/PoissonDisk.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <optional>

namespace penumbra::shadows {

glm::uvec2 pcg2d(glm::uvec2 v)
{
    v = v * 1664525u + 1013904223u;
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v ^= v >> 16u;
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v ^= v >> 16u;
    return v;
}

float diskRotationAngle(glm::ivec2 texel, Toggle rotation)
{
    if (rotation == Toggle::Off)
        return 0.0f;
    const glm::uvec2 h = pcg2d(glm::uvec2(static_cast<std::uint32_t>(texel.x), static_cast<std::uint32_t>(texel.y)));
    // 24 bits: exact in a float, the same on every backend.
    return 6.28318531f * (static_cast<float>(h.x >> 8u) * (1.0f / 16777216.0f));
}

glm::vec2 receiverPlaneDepthGradient(glm::vec3 dx, glm::vec3 dy)
{
    const float determinant = dx.x * dy.y - dx.y * dy.x;
    if (!(std::abs(determinant) > 1e-12f))
        return glm::vec2(0.0f);
    const glm::vec2 g{dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z};
    return g / determinant;
}

float orthographicDistanceFromNear(float depth, glm::vec2 depthRow) { return (depthRow.y - depth) / depthRow.x; }

float perspectiveDistance(float depth, glm::vec2 depthRow) { return depthRow.y / (depth + depthRow.x); }

SoftShadowUniforms softShadowUniforms(const SoftShadowSettings& soft)
{
    return {.searchScale = soft.blockerSearchScale,
            .penumbraScale = soft.penumbraScale,
            .minTexels = soft.minPenumbraTexels,
            .maxTexels = soft.maxPenumbraTexels,
            .blockerSamples = static_cast<std::int32_t>(soft.blockerSamples),
            .filterSamples = static_cast<std::int32_t>(soft.filterSamples),
            .poissonRadius = soft.poissonRadiusTexels,
            .diskRotation = soft.diskRotation == Toggle::On ? 1 : 0};
}

float tanHalfAngularDiameter(float degrees) { return std::tan(0.5f * degrees * 0.0174532925f); }

PenumbraLimits penumbraLimits(const SoftShadowSettings& soft)
{
    return {soft.minPenumbraTexels, soft.maxPenumbraTexels};
}

float directionalPenumbraTexels(float receiverToBlocker, float tanHalfAngle, float texelWorld, float scale)
{
    return scale * std::max(receiverToBlocker, 0.0f) * tanHalfAngle / texelWorld;
}

float directionalSearchTexels(float receiverFromNear, float tanHalfAngle, float texelWorld, float scale,
                              PenumbraLimits limits)
{
    return std::clamp(scale * std::max(receiverFromNear, 0.0f) * tanHalfAngle / texelWorld, 1.0f,
                      std::max(limits.maxTexels, 1.0f));
}

float perspectivePenumbraTexels(float receiverDistance, float blockerDistance, float lightTexels, float scale)
{
    return scale * lightTexels * std::max(receiverDistance - blockerDistance, 0.0f) /
           (blockerDistance * receiverDistance);
}

float diskRadius(float penumbra, float tapVariance, PenumbraLimits limits)
{
    return std::clamp(std::sqrt(std::max(penumbra * penumbra - 4.0f * tapVariance, 0.0f)), limits.minTexels,
                      limits.maxTexels);
}

float perspectiveSearchTexels(float receiverDistance, float nearPlane, float lightTexels, float scale,
                              PenumbraLimits limits)
{
    const float w = lightTexels * std::max(receiverDistance - nearPlane, 0.0f) / (receiverDistance * nearPlane);
    return std::clamp(scale * w, 1.0f, std::max(limits.maxTexels, 1.0f));
}

glm::ivec2 clampTapTexel(glm::vec2 position, glm::ivec2 tileMin, glm::ivec2 tileMax)
{
    return glm::clamp(glm::ivec2(glm::floor(position)), tileMin, tileMax);
}

std::vector<glm::vec2> poissonTaps(glm::vec2 centre, float radius, float angle, std::uint32_t count)
{
    const float c = std::cos(angle), s = std::sin(angle);
    std::vector<glm::vec2> taps;
    for (const glm::vec2& p : poissonDisk(count))
        taps.push_back(centre + radius * glm::vec2(c * p.x - s * p.y, s * p.x + c * p.y));
    return taps;
}

BlockerSearch searchBlockers(const DepthTileView& tile, glm::vec2 centre, float depth, glm::vec2 gradient, float radius,
                             float angle, std::uint32_t count)
{
    BlockerSearch result;
    result.nearestDepth = depth;
    float sum = 0.0f;
    const auto blockerAt = [&](glm::vec2 position) -> std::optional<float> {
        const glm::ivec2 texel = clampTapTexel(position, tile.tileMin, tile.tileMax);
        const float stored = tile.depthAt(texel);
        if (tile.isNearer(stored, depth + glm::dot(gradient, glm::vec2(texel) + 0.5f - centre)))
            return stored;
        return std::nullopt;
    };
    for (const glm::vec2& tap : poissonTaps(centre, radius, angle, count))
        if (const std::optional<float> stored = blockerAt(tap)) {
            sum += *stored;
            ++result.blockers;
            result.nearestDepth = tile.isNearer(*stored, result.nearestDepth) ? *stored : result.nearestDepth;
        }
    if (result.blockers == 0)
        if (const std::optional<float> stored = blockerAt(centre))
            return {.averageDepth = *stored, .blockers = 1, .nearestDepth = *stored};
    if (result.blockers > 0)
        result.averageDepth = sum / static_cast<float>(result.blockers);
    return result;
}

} // namespace penumbra::shadows
