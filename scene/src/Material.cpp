#include "penumbra/scene/Material.hpp"

#include <cmath>

namespace penumbra::scene {

float materialAlpha(const Material& material, glm::vec2 uv)
{
    if (material.caster != CasterMode::Clip)
        return material.baseColor.a;
    const auto cellX = static_cast<long>(std::floor(uv.x * kClipCheckerCells));
    const auto cellY = static_cast<long>(std::floor(uv.y * kClipCheckerCells));
    const bool odd = ((cellX + cellY) & 1) != 0;
    return odd ? 0.0f : material.baseColor.a;
}

} // namespace penumbra::scene
