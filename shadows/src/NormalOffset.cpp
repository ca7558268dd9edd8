#include "penumbra/shadows/NormalOffset.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {

glm::vec3 receiverNormalOffset(glm::vec3 geometricNormal, glm::vec3 towardsLight, float reach)
{
    const glm::vec3 n = glm::dot(geometricNormal, towardsLight) < 0.0f ? -geometricNormal : geometricNormal;
    const float cosine = glm::dot(n, towardsLight);
    return n * (reach * std::sqrt(std::max(1.0f - cosine * cosine, 0.0f)));
}

float normalOffsetReach(float normalBias, float texelSize, ShadowFilter filter)
{
    return normalBias * texelSize * normalBiasFilterFactor(filter) * 1.41421356f;
}

} // namespace penumbra::shadows
