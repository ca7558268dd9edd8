#include "ShadowTestSupport.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/AtlasMatrix.hpp"
#include "penumbra/shadows/DirectionalCascadeFit.hpp"
#include "penumbra/shadows/ShadowAtlasLayout.hpp"
#include "penumbra/shadows/TentFilterReference.hpp"

#include <gtest/gtest.h>
#include <optional>

namespace penumbra::shadows {
namespace {

TEST(ShadowAtlasLayout, SplitFollowsTheTileCount)
{
    EXPECT_EQ(ShadowAtlasLayout(1024, 0).split(), 1u);
    EXPECT_EQ(ShadowAtlasLayout(1024, 1).split(), 1u);
    for (std::uint32_t tiles = 2; tiles <= 4; ++tiles)
        EXPECT_EQ(ShadowAtlasLayout(1024, tiles).split(), 2u);
    for (std::uint32_t tiles = 5; tiles <= 16; ++tiles)
        EXPECT_EQ(ShadowAtlasLayout(1024, tiles).split(), 4u);
    EXPECT_EQ(ShadowAtlasLayout(2048, 6).tileSize(), 512u);
    EXPECT_THROW(ShadowAtlasLayout(1024, 65), rhi::Error);
    EXPECT_EQ(ShadowAtlasLayout(1024, 17).split(), 8u);
}

TEST(ShadowAtlasLayout, WithThreeCutsFiveToNineTilesThreeByThree)
{
    for (std::uint32_t tiles = 0; tiles <= 64; ++tiles) {
        const ShadowAtlasLayout powers(2048, tiles);
        const ShadowAtlasLayout three(2048, tiles, AtlasSplits::WithThree);
        EXPECT_EQ(three.split(), tiles >= 5 && tiles <= 9 ? 3u : powers.split()) << tiles;
    }
    // 2048 / 3 rounds down to 682: the last two texel columns and rows belong to no tile.
    const ShadowAtlasLayout layout(2048, 7, AtlasSplits::WithThree);
    EXPECT_EQ(layout.tileSize(), 682u);
    EXPECT_EQ(layout.tileOffset(5), glm::uvec2(1364, 682));
    EXPECT_EQ(layout.tileTexelBounds(8), (TileTexelBounds{{1364, 1364}, {2045, 2045}}));
    // Tile uv (0, 0) and (1, 1) land on the tile's first texel's corner and its last texel's far corner.
    const glm::vec4 topLeft = layout.tileToAtlas(5) * glm::vec4(0.0f, 0.0f, 0.3f, 1.0f);
    const glm::vec4 bottomRight = layout.tileToAtlas(5) * glm::vec4(1.0f, 1.0f, 0.3f, 1.0f);
    EXPECT_FLOAT_EQ(topLeft.x * 2048.0f, 1364.0f);
    EXPECT_FLOAT_EQ(topLeft.y * 2048.0f, 682.0f);
    EXPECT_FLOAT_EQ(bottomRight.x * 2048.0f, 2046.0f);
    EXPECT_FLOAT_EQ(bottomRight.y * 2048.0f, 1364.0f);
    EXPECT_THROW(ShadowAtlasLayout(2, 9, AtlasSplits::WithThree), rhi::Error);
}

TEST(ShadowAtlasLayout, TilesRunAlongRowsCountedFromTheTop)
{
    const ShadowAtlasLayout layout(1024, 16);
    EXPECT_EQ(layout.tileOffset(0), glm::uvec2(0, 0));
    EXPECT_EQ(layout.tileOffset(3), glm::uvec2(768, 0));
    EXPECT_EQ(layout.tileOffset(6), glm::uvec2(512, 256));
    const rhi::Viewport v = layout.viewport(13);
    EXPECT_EQ(v.x, 256.0f);
    EXPECT_EQ(v.y, 768.0f);
    EXPECT_EQ(v.width, 256.0f);
    EXPECT_EQ(v.height, 256.0f);
    EXPECT_EQ(directionalTileIndex(2, 1, 4), 9u);
    // Tile uv (0, 0) and (1, 1) are the tile's top-left and bottom-right corners in the atlas.
    const glm::vec4 topLeft = layout.tileToAtlas(6) * glm::vec4(0.0f, 0.0f, 0.3f, 1.0f);
    const glm::vec4 bottomRight = layout.tileToAtlas(6) * glm::vec4(1.0f, 1.0f, 0.3f, 1.0f);
    EXPECT_FLOAT_EQ(topLeft.x, 0.5f);
    EXPECT_FLOAT_EQ(topLeft.y, 0.25f);
    EXPECT_FLOAT_EQ(topLeft.z, 0.3f);
    EXPECT_FLOAT_EQ(bottomRight.x, 0.75f);
    EXPECT_FLOAT_EQ(bottomRight.y, 0.5f);
}

// A world point lands on the same atlas texel in every convention, on the pixel the rasterizer
// covers through the tile's viewport, and depths keep their meaning through shadowCompareOp.
TEST(WorldToAtlas, AgreesAcrossConventionsAndWithTheRasterizer)
{
    const ShadowAtlasLayout layout(2048, 8);
    const std::uint32_t tile = 5;
    const Sphere sphere{{3.0f, 1.0f, -8.0f}, 6.0f};
    const glm::vec3 light = glm::normalize(glm::vec3(0.3f, -1.0f, -0.4f));
    const glm::vec3 receiver = sphere.centre + glm::vec3(1.5f, -2.0f, 0.7f);
    const glm::vec3 occluder = receiver - light * 3.0f; // nearer to the light, same texel
    std::optional<glm::vec2> firstUv;
    for (const rhi::Conventions& conventions : testing::allConventions()) {
        SCOPED_TRACE(testing::conventionName(conventions));
        const DirectionalShadowCascade fit = fitDirectionalCascade(sphere, lightSpaceCasters(lightBasis(light), {}),
                                                                   layout.tileSize(), 0.0f, conventions);
        const glm::mat4 m = worldToAtlas(fit.viewProjection, tile, layout, conventions);
        const glm::vec4 r = m * glm::vec4(receiver, 1.0f);
        const glm::vec4 o = m * glm::vec4(occluder, 1.0f);
        EXPECT_NEAR(r.x, o.x, 1e-6f);
        EXPECT_NEAR(r.y, o.y, 1e-6f);
        if (!firstUv)
            firstUv = glm::vec2(r);
        EXPECT_NEAR(r.x, firstUv->x, 1e-6f);
        EXPECT_NEAR(r.y, firstUv->y, 1e-6f);

        // The rasterizer: NDC through the tile's viewport (y rows from the top), window depth per range.
        const glm::vec4 clip = fit.viewProjection * glm::vec4(receiver, 1.0f);
        const rhi::Viewport v = layout.viewport(tile);
        const float size = static_cast<float>(layout.atlasSize());
        EXPECT_NEAR(r.x * size, v.x + (0.5f * clip.x + 0.5f) * v.width, 1e-3f);
        EXPECT_NEAR(r.y * size, v.y + (0.5f - 0.5f * clip.y) * v.height, 1e-3f);
        EXPECT_NEAR(r.z, testing::rasterizerWindowDepth(conventions, clip), 1e-6f);

        // The occluder is nearer the light: stored there, the receiver fails the shadow compare.
        const bool nearerIsLess = !conventions.reversedZ();
        EXPECT_EQ(o.z < r.z, nearerIsLess);
        auto lit = [&](float reference, float stored) {
            const ShadowDepthGrid texel{1, 1, {stored}};
            return compareTexel(texel, 0, 0, reference, conventions.shadowCompareOp()) == 1.0f;
        };
        EXPECT_FALSE(lit(r.z, o.z));
        EXPECT_TRUE(lit(o.z, r.z));
        EXPECT_TRUE(lit(r.z, r.z));
    }
}

} // namespace
} // namespace penumbra::shadows
