#include "penumbra/render/AtlasPicture.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::render {

std::vector<PerspectiveTile> perspectiveTiles(const shadows::LocalShadowPlan& plan)
{
    std::vector<PerspectiveTile> tiles;
    for (const shadows::LocalAtlasTile& tile : plan.tiles)
        tiles.push_back({tile.viewport, tile.view.projection});
    return tiles;
}

std::vector<PerspectiveTile> perspectiveTiles(const shadows::StaticShadowPlan& plan)
{
    std::vector<PerspectiveTile> tiles;
    for (const shadows::StaticShadowMap& map : plan.maps)
        if (map.kind != shadows::LightKind::Directional)
            for (const shadows::StaticShadowTile& tile : map.tiles)
                tiles.push_back({tile.viewport, tile.projection});
    return tiles;
}

namespace {

// A depth nearer the far plane than half the float spacing below 1.0 (2^-24 there, IEEE 754 binary32) is stored as
// the far plane's 1.0 in a buffer that keeps far at 1, where it reads as the clear: it is the far plane in every
// convention, or a caster crossing a tile's far plane would leave texels drawn in a reversed-Z atlas only.
constexpr float kFarPlaneRounding = 0x1p-25f;

} // namespace

std::vector<float> lightDepthFraction(const rhi::DepthImage& atlas, const rhi::Conventions& conventions,
                                      std::span<const PerspectiveTile> perspectiveTiles)
{
    const float near = conventions.nearDepth();
    const float far = conventions.farDepth();
    std::vector<float> fraction(atlas.depth.size());
    for (std::size_t i = 0; i < atlas.depth.size(); ++i) {
        const float f = std::clamp((atlas.depth[i] - far) / (near - far), 0.0f, 1.0f);
        fraction[i] = f < kFarPlaneRounding ? 0.0f : f;
    }
    for (const PerspectiveTile& tile : perspectiveTiles) {
        const float nearView = conventions.viewDepth(tile.projection, near);
        const float farView = conventions.viewDepth(tile.projection, far);
        const auto x0 = static_cast<std::size_t>(tile.viewport.x);
        const auto y0 = static_cast<std::size_t>(tile.viewport.y);
        for (std::size_t y = y0; y < y0 + static_cast<std::size_t>(tile.viewport.height); ++y)
            for (std::size_t x = x0; x < x0 + static_cast<std::size_t>(tile.viewport.width); ++x) {
                const std::size_t i = y * atlas.width + x;
                const float depth = conventions.viewDepth(tile.projection, atlas.depth[i]);
                fraction[i] = std::clamp((farView - depth) / (farView - nearView), 0.0f, 1.0f);
            }
    }
    return fraction;
}

rhi::Image atlasPicture(const rhi::DepthImage& atlas, const rhi::Conventions& conventions,
                        std::span<const PerspectiveTile> perspectiveTiles)
{
    rhi::Image picture{atlas.width, atlas.height, rhi::Format::RGBA8, {}};
    picture.bytes.resize(std::size_t(atlas.width) * atlas.height * 4);
    const std::vector<float> fraction = lightDepthFraction(atlas, conventions, perspectiveTiles);
    for (std::size_t i = 0; i < fraction.size(); ++i) {
        const float nearness = fraction[i];
        const auto grey = static_cast<std::byte>(std::lround(nearness * 255.0f));
        std::fill_n(picture.bytes.begin() + std::ptrdiff_t(i * 4), 3, grey);
        picture.bytes[i * 4 + 3] = std::byte{255};
    }
    return picture;
}

} // namespace penumbra::render
