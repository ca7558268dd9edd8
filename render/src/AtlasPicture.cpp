#include "penumbra/render/AtlasPicture.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::render {

std::vector<float> lightDepthFraction(const rhi::DepthImage& atlas, const rhi::Conventions& conventions)
{
    const float near = conventions.nearDepth();
    const float far = conventions.farDepth();
    std::vector<float> fraction(atlas.depth.size());
    for (std::size_t i = 0; i < atlas.depth.size(); ++i)
        fraction[i] = std::clamp((atlas.depth[i] - far) / (near - far), 0.0f, 1.0f);
    return fraction;
}

rhi::Image atlasPicture(const rhi::DepthImage& atlas, const rhi::Conventions& conventions)
{
    rhi::Image picture{atlas.width, atlas.height, rhi::Format::RGBA8, {}};
    picture.bytes.resize(std::size_t(atlas.width) * atlas.height * 4);
    const std::vector<float> fraction = lightDepthFraction(atlas, conventions);
    for (std::size_t i = 0; i < fraction.size(); ++i) {
        const float nearness = fraction[i];
        const auto grey = static_cast<std::byte>(std::lround(nearness * 255.0f));
        std::fill_n(picture.bytes.begin() + std::ptrdiff_t(i * 4), 3, grey);
        picture.bytes[i * 4 + 3] = std::byte{255};
    }
    return picture;
}

} // namespace penumbra::render
