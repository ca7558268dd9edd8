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

glm::vec2 textureUv(const std::optional<MaterialTexture>& texture, glm::vec2 uv0, glm::vec2 uv1)
{
    if (!texture)
        return uv0;
    return glm::vec2(texture->transform.matrix() * glm::vec3(texture->texCoord == 1 ? uv1 : uv0, 1.0f));
}

float textureAlpha(const TextureImage& texture, glm::vec2 uv)
{
    if (texture.width == 0 || texture.height == 0)
        return 1.0f;
    // Texel i covers [i, i + 1) / size; bilinear weights between the centres around uv (Vulkan 1.3
    // specification, section 16.8 "Texel Filtering"), wrapped for repeat addressing.
    const float x = uv.x * static_cast<float>(texture.width) - 0.5f;
    const float y = uv.y * static_cast<float>(texture.height) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const auto wrap = [](float i, std::uint32_t size) {
        const long n = static_cast<long>(size);
        return static_cast<std::size_t>(((static_cast<long>(i) % n) + n) % n);
    };
    const auto alpha = [&](float i, float j) {
        const std::size_t index = wrap(j, texture.height) * texture.width + wrap(i, texture.width);
        return static_cast<float>(texture.rgba[4 * index + 3]) / 255.0f;
    };
    const float top = alpha(x0, y0) * (1.0f - fx) + alpha(x0 + 1.0f, y0) * fx;
    const float bottom = alpha(x0, y0 + 1.0f) * (1.0f - fx) + alpha(x0 + 1.0f, y0 + 1.0f) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

float materialAlpha(const Material& material, glm::vec2 uv, const TextureImage* baseColor)
{
    if (baseColor)
        return material.baseColor.a * textureAlpha(*baseColor, uv);
    if (material.caster != CasterMode::Clip)
        return material.baseColor.a;
    const auto cellX = static_cast<long>(std::floor(uv.x * kClipCheckerCells));
    const auto cellY = static_cast<long>(std::floor(uv.y * kClipCheckerCells));
    const bool odd = ((cellX + cellY) & 1) != 0;
    return odd ? 0.0f : material.baseColor.a;
}

} // namespace penumbra::scene
