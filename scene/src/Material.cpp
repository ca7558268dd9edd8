#include "penumbra/scene/Material.hpp"

#include <cmath>

namespace penumbra::scene {

glm::mat3 TextureTransform::matrix() const
{
    const float c = std::cos(rotation), s = std::sin(rotation);
    // KHR_texture_transform: T * R * S with R = [[c, s], [-s, c]] in column-major order.
    return glm::mat3(glm::vec3(c * scale.x, -s * scale.x, 0.0f), glm::vec3(s * scale.y, c * scale.y, 0.0f),
                     glm::vec3(offset, 1.0f));
}

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
