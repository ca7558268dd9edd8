#include "penumbra/shadows/DirectionalSoftData.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra::shadows {

glm::vec2 lightTexelAnchor(const DirectionalShadowCascade& fit, const glm::mat4& worldToAtlas)
{
    const glm::vec3 origin = fit.basis.right * fit.snappedCentre.x + fit.basis.up * fit.snappedCentre.y;
    const auto atlasX = [&](glm::vec3 p) { return (worldToAtlas * glm::vec4(p, 1.0f)).x; };
    const auto atlasY = [&](glm::vec3 p) { return (worldToAtlas * glm::vec4(p, 1.0f)).y; };
    const float signX = atlasX(origin + fit.basis.right) > atlasX(origin) ? 1.0f : -1.0f;
    const float signY = atlasY(origin + fit.basis.up) > atlasY(origin) ? 1.0f : -1.0f;
    return {std::round(signX * fit.snappedCentre.x / fit.texelSize),
            std::round(signY * fit.snappedCentre.y / fit.texelSize)};
}

float casterTopDepth(const LightSpaceCasters& casters, float fallback)
{
    return casters.light.empty() ? fallback : casters.top;
}

glm::vec2 directionalDepthRow(const DirectionalShadowCascade& fit, float casterTop, const rhi::Conventions& conventions)
{
    const glm::mat4 toTexture = conventions.clipToTexture() * fit.projection;
    return {toTexture[2][2], toTexture[3][2] + toTexture[2][2] * (fit.nearDepth - casterTop)};
}

DirectionalTileSoft directionalTileSoft(const DirectionalShadowCascade& fit, const glm::mat4& worldToAtlas,
                                        const LightSpaceCasters& casters, const rhi::Conventions& conventions)
{
    return {.lightTexelAnchor = lightTexelAnchor(fit, worldToAtlas),
            .depthRow = directionalDepthRow(fit, casterTopDepth(casters, fit.nearDepth), conventions)};
}

} // namespace penumbra::shadows
