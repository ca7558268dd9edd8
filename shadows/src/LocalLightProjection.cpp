#include "penumbra/shadows/LocalLightProjection.hpp"

#include "penumbra/shadows/NormalOffset.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::shadows {
namespace {

constexpr float kSqrt2 = 1.41421356f;

// At distance 1 from the light: the texel size x filter factor, and the normal bias x that x sqrt 2.
struct UnitFieldOfView {
    float filterSize;
    float bias;
};

// A tile whose frustum reaches tanHalf to each side at distance 1 (1 for the cube's 90 degrees) spans 2 tanHalf world
// units there.
UnitFieldOfView unitFieldOfView(float tanHalf, std::uint32_t tileSize, ShadowFilter filter, float normalBias)
{
    const float texel = 2.0f * tanHalf / static_cast<float>(tileSize);
    const float filterSize = texel * normalBiasFilterFactor(filter);
    return {filterSize, normalBias * filterSize * kSqrt2};
}

// Catlike Coding, "Point and Spot Shadows", section 2.5: the normal bias and the filter size added on each side.
float widenedFieldOfView(float tanHalf, std::uint32_t tileSize, ShadowFilter filter, float normalBias)
{
    const UnitFieldOfView u = unitFieldOfView(tanHalf, tileSize, filter, normalBias);
    return 2.0f * std::atan(tanHalf + u.bias + u.filterSize);
}

} // namespace

glm::vec3 cubeFaceAxis(CubeFace face)
{
    constexpr std::array<glm::vec3, cubeFaceCount> axes{
        {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
    return axes[static_cast<std::size_t>(face)];
}

CubeFace cubeFace(glm::vec3 d)
{
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x >= 0.0f ? CubeFace::PositiveX : CubeFace::NegativeX;
    if (a.y >= a.z)
        return d.y >= 0.0f ? CubeFace::PositiveY : CubeFace::NegativeY;
    return d.z >= 0.0f ? CubeFace::PositiveZ : CubeFace::NegativeZ;
}

glm::mat4 pointFaceView(CubeFace face, glm::vec3 position)
{
    const glm::vec3 axis = cubeFaceAxis(face);
    const glm::vec3 up = axis.y != 0.0f ? glm::vec3(0.0f, 0.0f, -axis.y) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAtRH(position, position + axis, up);
}

glm::mat4 spotView(glm::vec3 position, glm::vec3 direction)
{
    const glm::vec3 up = std::abs(direction.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAtRH(position, position + direction, up);
}

float localShadowNearPlane(float range, float lightNearPlane, const LocalShadowSettings& settings)
{
    return lightNearPlane > 0.0f ? lightNearPlane : settings.nearPlane * range;
}

float texelSizeAtUnitDistance(const glm::mat4& projection, std::uint32_t tileSize)
{
    return 2.0f / (static_cast<float>(tileSize) * projection[0][0]);
}

PerspectiveTileSoft perspectiveTileSoft(const glm::mat4& projection, std::uint32_t tileSize, float sourceRadius,
                                        float nearPlane, const rhi::Conventions& conventions)
{
    const glm::mat4 toTexture = conventions.clipToTexture() * projection;
    return {.depthRow = {toTexture[2][2], toTexture[3][2]},
            .lightTexels = sourceRadius / texelSizeAtUnitDistance(projection, tileSize),
            .nearPlane = nearPlane};
}

float localNormalBiasScale(const glm::mat4& projection, std::uint32_t tileSize, ShadowFilter filter, float normalBias)
{
    return normalOffsetReach(normalBias, texelSizeAtUnitDistance(projection, tileSize), filter);
}

float pointFaceFieldOfView(std::uint32_t tileSize, ShadowFilter filter, float normalBias)
{
    return widenedFieldOfView(1.0f, tileSize, filter, normalBias);
}

float spotFieldOfView(float outerAngle, std::uint32_t tileSize, ShadowFilter filter, float normalBias, Toggle fovBias)
{
    if (fovBias == Toggle::Off)
        return 2.0f * outerAngle;
    return widenedFieldOfView(std::tan(outerAngle), tileSize, filter, normalBias);
}

float pointFaceFovBiasDegrees(std::uint32_t tileSize, ShadowFilter filter, float normalBias)
{
    return glm::degrees(pointFaceFieldOfView(tileSize, filter, normalBias)) - 90.0f;
}

} // namespace penumbra::shadows
