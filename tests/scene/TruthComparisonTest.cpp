// scene::compareWithTruth on hand-made pictures: verdicts, per-class figures, the edge margin.
#include "penumbra/scene/TruthComparison.hpp"

#include <gtest/gtest.h>

namespace penumbra::scene {
namespace {

constexpr std::uint32_t kSize = 16;

// One object everywhere; the ray cast says lit left of column 8, shadowed from it on.
struct Pictures {
    CpuGBuffer gbuffer{kSize, kSize, std::vector<GBufferSample>(kSize* kSize)};
    LightVisibilityMask truth{kSize, kSize, std::vector<LightVisibility>(kSize* kSize)};
    RenderedVisibility rendered{kSize, kSize, std::vector<float>(kSize* kSize),
                                std::vector<std::uint8_t>(kSize* kSize, 1)};

    Pictures()
    {
        for (std::uint32_t y = 0; y < kSize; ++y)
            for (std::uint32_t x = 0; x < kSize; ++x) {
                const std::size_t i = y * kSize + x;
                gbuffer.samples[i].object = 0;
                truth.pixels[i] = x < 8 ? LightVisibility::Lit : LightVisibility::Shadowed;
                rendered.lit[i] = x < 8 ? 1.0f : 0.0f;
            }
    }
    std::size_t at(std::uint32_t x, std::uint32_t y) const { return y * kSize + x; }
};

TEST(TruthComparisonTest, AgreeingPicturesAreRightAwayFromEdges)
{
    const Pictures p;
    const TruthComparison c = compareWithTruth(p.gbuffer, p.truth, p.rendered);
    // The picture's border and two columns either side of the shadow edge are edges.
    EXPECT_EQ(c.lit.compared, std::size_t(12 * 4));
    EXPECT_EQ(c.shadowed.compared, std::size_t(12 * 4));
    EXPECT_EQ(c.lit.right, c.lit.compared);
    EXPECT_EQ(c.shadowed.right, c.shadowed.compared);
    EXPECT_EQ(c.lit.nearEdges + c.shadowed.nearEdges, std::size_t(kSize * kSize - 96));
    EXPECT_EQ(c.agreement(), 1.0);
    EXPECT_EQ(c.at(4, 8), TruthVerdict::LitRight);
    EXPECT_EQ(c.at(7, 8), TruthVerdict::NearEdge);
}

TEST(TruthComparisonTest, WrongPixelsAreAcneAndLeaks)
{
    Pictures p;
    p.rendered.lit[p.at(4, 8)] = 0.2f; // truly lit, rendered dark
    p.rendered.lit[p.at(11, 8)] = 0.6f; // truly shadowed, rendered lit
    p.rendered.lit[p.at(12, 8)] = 0.5f; // exactly half: lit
    const TruthComparison c = compareWithTruth(p.gbuffer, p.truth, p.rendered);
    EXPECT_EQ(c.acne(), 1u);
    EXPECT_EQ(c.leaks(), 2u);
    EXPECT_EQ(c.at(4, 8), TruthVerdict::Acne);
    EXPECT_EQ(c.at(11, 8), TruthVerdict::Leak);
    EXPECT_DOUBLE_EQ(c.shadowed.share(), 46.0 / 48.0);
}

TEST(TruthComparisonTest, PixelsTheShadowMapDoesNotDecideAreLeftOut)
{
    Pictures p;
    p.rendered.decided[p.at(4, 8)] = 0;
    p.truth.pixels[p.at(4, 4)] = LightVisibility::FacingAway; // also makes its neighbours edges
    const TruthComparison c = compareWithTruth(p.gbuffer, p.truth, p.rendered);
    EXPECT_EQ(c.at(4, 8), TruthVerdict::Undecided);
    EXPECT_EQ(c.lit.undecided, 1u);
    EXPECT_EQ(c.at(4, 4), TruthVerdict::NotCompared);
    EXPECT_EQ(c.at(4, 5), TruthVerdict::NearEdge);
}

TEST(TruthComparisonTest, PicturesOfDifferentSizesAreRefused)
{
    Pictures p;
    p.rendered.width = 8;
    EXPECT_THROW(compareWithTruth(p.gbuffer, p.truth, p.rendered), std::invalid_argument);
}

} // namespace
} // namespace penumbra::scene
