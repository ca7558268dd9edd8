// truth::compareWithTruth on hand-made pictures: verdicts, per-class figures, the edge margin; and
// truth::confirmDisagreements on a ray-cast scene.
#include "penumbra/truth/TruthComparison.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::truth {
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

// Behind dithered casters only, a pixel's answer is the dither's: those pixels are judged by their mean, apart
// from the lit and shadowed classes, and their border is an edge like any change of class.
TEST(TruthComparisonTest, DitheredPixelsAreJudgedOnAverage)
{
    Pictures p;
    p.truth.ditherCoverage.assign(kSize * kSize, 0.0f);
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 8; x < kSize; ++x) {
            p.truth.pixels[p.at(x, y)] = LightVisibility::Dithered;
            p.truth.ditherCoverage[p.at(x, y)] = 0.6f;
            p.rendered.lit[p.at(x, y)] = (x + y) % 2 == 0 ? 1.0f : 0.0f; // a stipple, half lit
        }
    const TruthComparison c = compareWithTruth(p.gbuffer, p.truth, p.rendered);
    EXPECT_EQ(c.shadowed.compared, 0u);
    EXPECT_EQ(c.shadowed.share(), 1.0); // an empty class: none wrong
    EXPECT_EQ(c.leaks(), 0u);
    EXPECT_EQ(c.dithered.compared, std::size_t(12 * 4));
    EXPECT_NEAR(c.dithered.expectedLit(), 0.4, 1e-6);
    EXPECT_DOUBLE_EQ(c.dithered.renderedLit(), 0.5);
    EXPECT_EQ(c.at(11, 8), TruthVerdict::Dithered);
    EXPECT_EQ(c.at(8, 8), TruthVerdict::NotCompared); // within the margin of the lit side
    EXPECT_EQ(c.at(7, 8), TruthVerdict::NearEdge);
}

TEST(TruthComparisonTest, PicturesOfDifferentSizesAreRefused)
{
    Pictures p;
    p.rendered.width = 8;
    EXPECT_THROW(compareWithTruth(p.gbuffer, p.truth, p.rendered), std::invalid_argument);
}

// Ground seen from above, lit by a sun 45 degrees up towards -z, with a square slab of side 1.5 at x = -3 and one of
// side 4 at x = +3 floating 4 units over it, so that their shadows fall 4 units off them; the renderer's answer is
// lit everywhere, so every compared shadowed pixel is a leak.
struct SlabScene {
    static constexpr std::uint32_t kPixels = 128;
    scene::Scene scene;
    CpuGBuffer gbuffer;
    LightVisibilityMask truth;
    RenderedVisibility rendered;

    SlabScene()
    {
        const std::uint32_t material = scene.addMaterial({});
        scene.addObject("ground", scene.addMesh(scene::makePlane(10.0f)), material, glm::mat4(1.0f));
        for (const auto& [x, side] : {std::pair{-3.0f, 1.5f}, std::pair{3.0f, 4.0f}})
            scene.addObject("slab", scene.addMesh(scene::makeBox({0.5f * side, 0.05f, 0.5f * side})), material,
                            glm::translate(glm::mat4(1.0f), glm::vec3(x, 4.0f, 0.0f)));
        scene.lights.push_back({.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f))});
        scene.camera = scene::lookAt({0.0f, 14.0f, 4.0f}, {0.0f, 0.0f, 4.0f}, glm::radians(60.0f), {0.0f, 0.0f, -1.0f});
        gbuffer = traceGBuffer(scene, RayCaster(scene, RayKind::Camera), scene.camera, kPixels, kPixels);
        truth = traceLightVisibility(scene, RayCaster(scene), gbuffer, scene.lights[0]);
        rendered = {kPixels, kPixels, std::vector<float>(kPixels * kPixels, 1.0f),
                    std::vector<std::uint8_t>(kPixels * kPixels, 1)};
    }

    // Leak pixels under the slab centred at x.
    std::size_t leaksUnder(const TruthComparison& c, float x) const
    {
        std::size_t leaks = 0;
        for (std::size_t i = 0; i < c.verdicts.size(); ++i)
            leaks += c.verdicts[i] == TruthVerdict::Leak && std::abs(gbuffer.samples[i].position.x - x) < 2.5f;
        return leaks;
    }
};

// A shadow smaller than the lookup's footprint is beyond the map's resolution: its leaks become edges. The large
// slab's shadow, uniform across the footprint, keeps its leaks, and the figures follow the verdicts.
TEST(TruthComparisonTest, DisagreementsWithinAFootprintOfAnEdgeAreEdges)
{
    const SlabScene s;
    TruthComparison c = compareWithTruth(s.gbuffer, s.truth, s.rendered);
    const std::size_t smallLeaks = s.leaksUnder(c, -3.0f), largeLeaks = s.leaksUnder(c, 3.0f);
    ASSERT_GT(smallLeaks, 0u) << "the small slab's shadow must hold compared pixels";
    ASSERT_GT(largeLeaks, 100u);
    const std::size_t compared = c.shadowed.compared;
    std::vector<LookupFootprint> footprints(s.gbuffer.samples.size());
    for (std::size_t i = 0; i < footprints.size(); ++i)
        footprints[i] = {s.gbuffer.samples[i].position, 1.0f};
    confirmDisagreements(c, RayCaster(s.scene), s.gbuffer, s.truth, raysTowards(s.scene.lights[0]), footprints);
    EXPECT_EQ(s.leaksUnder(c, -3.0f), 0u);
    const std::size_t kept = s.leaksUnder(c, 3.0f);
    EXPECT_GT(kept, 0u) << "the large shadow's middle is uniform over a footprint";
    EXPECT_LT(kept, largeLeaks) << "its rim is within a footprint of its edge";
    EXPECT_EQ(c.shadowed.compared, compared - (smallLeaks + largeLeaks - kept));
    EXPECT_EQ(c.leaks(), kept);
}

TEST(TruthComparisonTest, ConfirmingNeedsAFootprintPerPixel)
{
    const SlabScene s;
    TruthComparison c = compareWithTruth(s.gbuffer, s.truth, s.rendered);
    EXPECT_THROW(confirmDisagreements(c, RayCaster(s.scene), s.gbuffer, s.truth, raysTowards(s.scene.lights[0]), {}),
                 std::invalid_argument);
}

// Contact gaps keep the pixels near shadow edges that the comparison leaves out, and count only casters within reach
// along the rays: the slabs' undersides are 3.95 units up, 5.59 along the 45-degree rays.
TEST(TruthComparisonTest, ContactGapsKeepEdgesAndCountCastersWithinReach)
{
    const SlabScene s;
    const RayCaster shadowRays(s.scene);
    const ShadowRayFrom rays = raysTowards(s.scene.lights[0]);
    const TruthComparison c = compareWithTruth(s.gbuffer, s.truth, s.rendered);
    const ContactGapFigures within = contactGapPixels(s.gbuffer, s.truth, s.rendered, shadowRays, rays, 6.0f);
    EXPECT_GT(within.gaps, c.leaks()) << "the pixels near the shadows' edges count";
    EXPECT_EQ(within.gaps, within.shadowed) << "the renderer's answer is lit everywhere";
    EXPECT_EQ(contactGapPixels(s.gbuffer, s.truth, s.rendered, shadowRays, rays, 5.0f).shadowed, 0u);
    RenderedVisibility dark = s.rendered;
    std::fill(dark.lit.begin(), dark.lit.end(), 0.0f);
    EXPECT_EQ(contactGapPixels(s.gbuffer, s.truth, dark, shadowRays, rays, 6.0f).gaps, 0u);
}

} // namespace
} // namespace penumbra::truth
