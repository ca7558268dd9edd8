#include "penumbra/rhi/Error.hpp"
#include "ShadowTestSupport.hpp"

#include "penumbra/shadows/CascadeData.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/FilterConstants.hpp"
#include "penumbra/shadows/PoissonDisk.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"
#include "penumbra/shadows/SoftShadowMath.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <set>
#include <vector>
#include <string>

namespace penumbra::shadows {
namespace {

using testing::allConventions;
using testing::conventionName;

TEST(PoissonDiskTest, PointsLieInTheUnitDiskAndKeepApart)
{
    for (const std::uint32_t count : kPoissonSampleCounts) {
        const std::span<const glm::vec2> disk = poissonDisk(count);
        ASSERT_EQ(disk.size(), count);
        float nearest = 10.0f;
        glm::vec2 mean(0.0f);
        for (std::size_t i = 0; i < disk.size(); ++i) {
            EXPECT_LE(glm::length(disk[i]), 1.0f);
            mean += disk[i] / static_cast<float>(count);
            for (std::size_t j = i + 1; j < disk.size(); ++j)
                nearest = std::min(nearest, glm::distance(disk[i], disk[j]));
        }
        // The densest packing of n points in the unit disk keeps about 1.9 / sqrt(n) apart, the spiral 1.55 /
        // sqrt(n); random points come far closer (their expected nearest pair is about 1 / n).
        EXPECT_GT(nearest, 1.5f / std::sqrt(static_cast<float>(count))) << count;
        // Centred: a turning disk whose mean lies off the centre shifts every estimate by it.
        EXPECT_LT(glm::length(mean), 1e-6f) << count;
    }
}

TEST(PoissonDiskTest, PointsAreUniformOverTheDiskArea)
{
    // A filter of radius r over the disk blurs as the uniform disk of radius r only if the points' radii are
    // distributed as a uniform disk's (P(radius < s) = s^2): the spiral's k-th point at sqrt((k + 0.5) / n), mean
    // squared radius 1/2, less the square of the mean the centring takes away.
    for (const std::uint32_t count : kPoissonSampleCounts) {
        const std::span<const glm::vec2> disk = poissonDisk(count);
        const glm::vec2 shift = spiralMean(count);
        EXPECT_LT(glm::length(shift), 0.031f) << count;
        float meanSquared = 0.0f;
        for (std::size_t k = 0; k < disk.size(); ++k) {
            EXPECT_NEAR(glm::length(disk[k] + shift),
                        std::sqrt((static_cast<float>(k) + 0.5f) / static_cast<float>(count)), 1e-6f)
                << count << " point " << k;
            meanSquared += glm::dot(disk[k], disk[k]) / static_cast<float>(count);
        }
        EXPECT_NEAR(meanSquared, 0.5f - glm::dot(shift, shift), 1e-5f) << count;
    }
}

// The shaders' walk (soft_shadows.glsl, nextDiskPoint): point k's direction is point k - 1's turned by the golden
// angle, from (1, 0).
TEST(PoissonDiskTest, EachPointTurnsTheGoldenAngleFromTheLast)
{
    for (const std::uint32_t count : kPoissonSampleCounts) {
        const std::span<const glm::vec2> disk = poissonDisk(count);
        const glm::vec2 turn{std::cos(kGoldenAngle), std::sin(kGoldenAngle)};
        glm::vec2 direction{1.0f, 0.0f};
        for (std::size_t k = 0; k < disk.size(); ++k) {
            const glm::vec2 walked =
                std::sqrt((static_cast<float>(k) + 0.5f) / static_cast<float>(count)) * direction - spiralMean(count);
            EXPECT_NEAR(walked.x, disk[k].x, 1e-5f) << count << " point " << k;
            EXPECT_NEAR(walked.y, disk[k].y, 1e-5f) << count << " point " << k;
            direction = {turn.x * direction.x - turn.y * direction.y, turn.y * direction.x + turn.x * direction.y};
        }
    }
}

TEST(PoissonDiskTest, IsTheSameEveryCallAndRefusesOtherCounts)
{
    EXPECT_EQ(poissonDisk(16).data(), poissonDisk(16).data());
    EXPECT_THROW(poissonDisk(24), rhi::Error);
    EXPECT_THROW(spiralMean(24), rhi::Error);
}

TEST(FilterConstantsTest, WritesEveryFilterAndTheSpiralOnce)
{
    const std::string glsl = filterConstantsGlsl();
    EXPECT_NE(glsl.find("#define PENUMBRA_FILTER_PCF2X2 0\n"), std::string::npos);
    EXPECT_NE(glsl.find("#define PENUMBRA_FILTER_POISSON 4\n"), std::string::npos);
    EXPECT_NE(glsl.find("#define PENUMBRA_FILTER_PCSS 5\n"), std::string::npos);
    EXPECT_NE(glsl.find("PENUMBRA_FILTER_SIZES[6] = int[](2, 3, 5, 7, 2, 2)"), std::string::npos);
    EXPECT_NE(glsl.find(fmt::format("const vec2 PENUMBRA_GOLDEN_TURN = vec2({:.9g}, {:.9g});\n", std::cos(kGoldenAngle),
                                    std::sin(kGoldenAngle))),
              std::string::npos);
    const glm::vec2 m16 = spiralMean(16), m64 = spiralMean(64);
    EXPECT_NE(glsl.find(fmt::format("count == 16 ? vec2({:.9g}, {:.9g}) :", m16.x, m16.y)), std::string::npos);
    EXPECT_NE(glsl.find(fmt::format(": vec2({:.9g}, {:.9g}); }}", m64.x, m64.y)), std::string::npos);
}

TEST(RotationHashTest, IsDeterministicAndSpreadsAngles)
{
    // PCG2D of (0, 0), worked by hand from the paper's constants: v = (1013904223, 1013904223) first.
    EXPECT_EQ(pcg2d(glm::uvec2(0u)), pcg2d(glm::uvec2(0u)));
    std::set<int> bins;
    float sum = 0.0f;
    for (int y = -8; y < 8; ++y)
        for (int x = -8; x < 8; ++x) {
            const float a = diskRotationAngle({x, y});
            ASSERT_GE(a, 0.0f);
            ASSERT_LT(a, 6.2831854f);
            bins.insert(static_cast<int>(a / 6.2831854f * 16.0f));
            sum += a;
        }
    EXPECT_EQ(bins.size(), 16u); // every sixteenth of the circle is used by 256 texels
    EXPECT_NEAR(sum / 256.0f, 3.14159f, 0.4f);
    EXPECT_NE(diskRotationAngle({1, 0}), diskRotationAngle({0, 1}));
}

// soft.diskRotation off: every receiver reads the unturned disk, and the lit shader is told so.
TEST(RotationHashTest, TheToggleTurnsTheRotationOff)
{
    for (const glm::ivec2 texel : {glm::ivec2(1, 0), glm::ivec2(0, 1), glm::ivec2(-7, 12)}) {
        EXPECT_EQ(diskRotationAngle(texel, Toggle::Off), 0.0f);
        EXPECT_EQ(diskRotationAngle(texel, Toggle::On), diskRotationAngle(texel));
    }
    SoftShadowSettings soft;
    EXPECT_EQ(softShadowUniforms(soft).diskRotation, 1);
    soft.diskRotation = Toggle::Off;
    EXPECT_EQ(softShadowUniforms(soft).diskRotation, 0);
}

TEST(ReceiverPlaneTest, RecoversThePlaneGradientFromScreenDerivatives)
{
    // A plane depth = 0.01 x + 0.002 y seen through an arbitrary screen mapping.
    const glm::vec2 g{0.01f, 0.002f};
    const glm::vec2 dx{1.5f, 0.25f}, dy{-0.5f, 2.0f};
    const glm::vec2 recovered = receiverPlaneDepthGradient({dx, glm::dot(g, dx)}, {dy, glm::dot(g, dy)});
    EXPECT_NEAR(recovered.x, g.x, 1e-6f);
    EXPECT_NEAR(recovered.y, g.y, 1e-6f);
    EXPECT_EQ(receiverPlaneDepthGradient({1, 1, 1}, {2, 2, 2}), glm::vec2(0.0f)); // edge-on
}

TEST(PenumbraTest, DirectionalPenumbraIsTheSameInWorldUnitsInEveryCascade)
{
    const float tanHalf = tanHalfAngularDiameter(2.0f);
    // One blocker 3 world units above its receiver, seen by cascades of texel size 0.02 and 0.08: 4x fewer texels
    // in the coarse cascade, the same world radius.
    const float fine = directionalPenumbraTexels(3.0f, tanHalf, 0.02f, 1.0f);
    const float coarse = directionalPenumbraTexels(3.0f, tanHalf, 0.08f, 1.0f);
    EXPECT_NEAR(fine * 0.02f, coarse * 0.08f, 1e-5f);
    EXPECT_NEAR(fine * 0.02f, 3.0f * std::tan(0.0174533f), 1e-5f);
    // Contact hardening: twice the distance, twice the penumbra.
    EXPECT_NEAR(directionalPenumbraTexels(6.0f, tanHalf, 0.02f, 1.0f), 2.0f * fine, 1e-4f);
    EXPECT_EQ(directionalPenumbraTexels(0.0f, tanHalf, 0.02f, 1.0f), 0.0f);
    EXPECT_EQ(directionalSearchTexels(0.0f, tanHalf, 0.02f, 1.0f, {0.0f, 24.0f}), 1.0f);
}

// The disk of radius r blurs by r^2 / 4 per axis, a bilinear tap by 1 / 6 more: the disk whose blur with its taps'
// is the penumbra's disk, measured on the taps themselves.
TEST(PenumbraTest, DiskRadiusLeavesRoomForTheTapsOwnBlur)
{
    const PenumbraLimits wide{0.0f, 64.0f};
    for (const float penumbra : {2.0f, 5.0f, 12.0f}) {
        const float r = diskRadius(penumbra, kBilinearTapVariance, wide);
        float variance = 0.0f;
        for (const glm::vec2& p : poissonDisk(64))
            variance += r * r * p.x * p.x / 64.0f;
        EXPECT_NEAR(variance + kBilinearTapVariance, penumbra * penumbra / 4.0f, 0.02f * penumbra * penumbra)
            << penumbra;
    }
    EXPECT_NEAR(diskRadius(3.0f, kNearestTapVariance, wide), std::sqrt(9.0f - 1.0f / 3.0f), 1e-5f);
    // Where the taps alone blur as much, no disk; then the limits.
    EXPECT_EQ(diskRadius(0.5f, kBilinearTapVariance, wide), 0.0f);
    EXPECT_EQ(diskRadius(0.5f, kBilinearTapVariance, {1.0f, 24.0f}), 1.0f);
    EXPECT_EQ(diskRadius(100.0f, kBilinearTapVariance, {1.0f, 24.0f}), 24.0f);
}

TEST(PenumbraTest, PerspectiveFormsFollowFernando)
{
    const PenumbraLimits wide{0.0f, 1000.0f};
    // w_penumbra = R (zR - zB) / zB at the receiver, in texels of size zR / f: lightTexels (zR - zB) / (zB zR).
    EXPECT_NEAR(perspectivePenumbraTexels(4.0f, 2.0f, 100.0f, 1.0f), 100.0f * 2.0f / 8.0f, 1e-4f);
    EXPECT_EQ(perspectivePenumbraTexels(4.0f, 4.0f, 100.0f, 1.0f), 0.0f);
    // w_search = R (zR - n) / zR at the near plane, in its texels (n / f).
    EXPECT_NEAR(perspectiveSearchTexels(4.0f, 0.5f, 10.0f, 1.0f, wide), 10.0f * 3.5f / 2.0f, 1e-4f);
    EXPECT_NEAR(perspectiveSearchTexels(4.0f, 0.5f, 10.0f, 2.0f, wide), 35.0f, 1e-4f);
}

TEST(PenumbraTest, DepthRowsGiveDistances)
{
    // Orthographic depth = t22 viewZ + t32 with viewZ = -distance past the near plane.
    const glm::vec2 row{-0.1f, 0.0f};
    EXPECT_NEAR(orthographicDistanceFromNear(0.5f, row), 5.0f, 1e-5f);
    // Perspective depth = (t22 (-z) + t32) / z.
    const glm::vec2 perspective{-1.0f, 2.0f};
    const float z = 4.0f;
    EXPECT_NEAR(perspectiveDistance((perspective.x * -z + perspective.y) / z, perspective), z, 1e-5f);
}

TEST(TapClampTest, EveryTapOfAWideDiskStaysInItsTile)
{
    const glm::ivec2 tileMin{256, 0}, tileMax{511, 255};
    for (const std::uint32_t count : kPoissonSampleCounts)
        for (const glm::vec2& tap : poissonTaps({258.3f, 3.1f}, 64.0f, 1.0f, count)) {
            const glm::ivec2 t = clampTapTexel(tap, tileMin, tileMax);
            EXPECT_GE(t.x, tileMin.x);
            EXPECT_GE(t.y, tileMin.y);
            EXPECT_LE(t.x, tileMax.x);
            EXPECT_LE(t.y, tileMax.y);
        }
}

TEST(BlockerSearchTest, AveragesOnlyNearerTexelsAndIgnoresTheSlopedReceiver)
{
    // Depth grows with x along a sloped receiver, 0.01 per texel; a blocker at depth 0.2 covers x < 100.
    DepthTileView tile;
    tile.tileMin = {0, 0};
    tile.tileMax = {255, 255};
    tile.isNearer = [](float a, float b) { return a < b - 1e-6f; };
    tile.depthAt = [](glm::ivec2 t) {
        return t.x < 100 ? 0.2f : 0.5f + 0.01f * (static_cast<float>(t.x) + 0.5f - 120.0f);
    };
    const glm::vec2 gradient{0.01f, 0.0f};
    // On the receiver far from the blocker: the plane matches every texel, no blocker.
    EXPECT_EQ(searchBlockers(tile, {180.0f, 50.0f}, 0.5f + 0.01f * 60.0f, gradient, 8.0f, 0.3f, 16).blockers, 0u);
    // Without the plane's gradient the sloped receiver shadows itself.
    EXPECT_GT(searchBlockers(tile, {180.0f, 50.0f}, 0.5f + 0.01f * 60.0f, glm::vec2(0.0f), 8.0f, 0.3f, 16).blockers,
              0u);
    // Straddling the blocker's edge: some blockers, all at 0.2.
    const BlockerSearch edge = searchBlockers(tile, {100.0f, 50.0f}, 0.5f - 0.01f * 20.0f, gradient, 8.0f, 0.3f, 32);
    EXPECT_GT(edge.blockers, 4u);
    EXPECT_LT(edge.blockers, 28u);
    EXPECT_FLOAT_EQ(edge.averageDepth, 0.2f);
}

// The refined search's input: two blockers, the nearer at 0.1 on x < 90, the farther at 0.3 on 90 <= x < 110; a
// search over both reports the nearer as the nearest and averages the two, one over the farther alone finds 0.3.
TEST(BlockerSearchTest, ReportsTheNearestBlocker)
{
    DepthTileView tile;
    tile.tileMin = {0, 0};
    tile.tileMax = {255, 255};
    tile.isNearer = [](float a, float b) { return a < b - 1e-6f; };
    tile.depthAt = [](glm::ivec2 t) { return t.x < 90 ? 0.1f : t.x < 110 ? 0.3f : 0.8f; };
    const BlockerSearch both = searchBlockers(tile, {100.0f, 50.0f}, 0.8f, glm::vec2(0.0f), 16.0f, 0.3f, 32);
    EXPECT_FLOAT_EQ(both.nearestDepth, 0.1f);
    EXPECT_GT(both.averageDepth, 0.1f);
    EXPECT_LT(both.averageDepth, 0.3f);
    const BlockerSearch farther = searchBlockers(tile, {104.0f, 50.0f}, 0.8f, glm::vec2(0.0f), 4.0f, 0.3f, 16);
    EXPECT_FLOAT_EQ(farther.nearestDepth, 0.3f);
    EXPECT_FLOAT_EQ(farther.averageDepth, 0.3f);
    EXPECT_FLOAT_EQ(searchBlockers(tile, {200.0f, 50.0f}, 0.8f, glm::vec2(0.0f), 8.0f, 0.3f, 16).nearestDepth, 0.8f);
}

// A caster one texel wide (a wire seen end on) right over the receiver, searched over 24 texels: the 16 taps,
// about 10 texels apart, step over it, and the receiver's own texel finds it.
TEST(BlockerSearchTest, FindsACasterThinnerThanTheTapsSpacingOverTheReceiver)
{
    DepthTileView tile;
    tile.tileMin = {0, 0};
    tile.tileMax = {255, 255};
    tile.isNearer = [](float a, float b) { return a < b - 1e-6f; };
    tile.depthAt = [](glm::ivec2 t) { return t == glm::ivec2(100, 50) ? 0.3f : 0.8f; };
    const glm::vec2 centre{100.5f, 50.5f};
    for (const glm::vec2& tap : poissonTaps(centre, 24.0f, 0.3f, 16))
        ASSERT_NE(clampTapTexel(tap, tile.tileMin, tile.tileMax), glm::ivec2(100, 50)) << "a tap reads the wire";
    const BlockerSearch wire = searchBlockers(tile, centre, 0.8f, glm::vec2(0.0f), 24.0f, 0.3f, 16);
    EXPECT_EQ(wire.blockers, 1u);
    EXPECT_FLOAT_EQ(wire.averageDepth, 0.3f);
    EXPECT_FLOAT_EQ(wire.nearestDepth, 0.3f);
    // Beside the wire nothing is found.
    EXPECT_EQ(searchBlockers(tile, centre + glm::vec2(2.0f, 0.0f), 0.8f, glm::vec2(0.0f), 24.0f, 0.3f, 16).blockers,
              0u);
}

TEST(SoftSettingsTest, ValidatesEveryControl)
{
    ShadowSettings s;
    EXPECT_NO_THROW(validate(s));
    const auto rejects = [](auto change, const char* field) {
        ShadowSettings bad;
        change(bad.soft);
        try {
            validate(bad);
            ADD_FAILURE() << field << " accepted";
        } catch (const rhi::Error& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    };
    rejects([](SoftShadowSettings& f) { f.blockerSearchScale = 0.0f; }, "soft.blockerSearchScale");
    rejects([](SoftShadowSettings& f) { f.penumbraScale = 11.0f; }, "soft.penumbraScale");
    rejects([](SoftShadowSettings& f) { f.blockerSamples = 20; }, "soft.blockerSamples");
    rejects([](SoftShadowSettings& f) { f.filterSamples = 128; }, "soft.filterSamples");
    rejects([](SoftShadowSettings& f) { f.minPenumbraTexels = -1.0f; }, "soft.minPenumbraTexels");
    rejects([](SoftShadowSettings& f) { f.maxPenumbraTexels = 0.5f; }, "soft.maxPenumbraTexels");
    rejects([](SoftShadowSettings& f) { f.poissonRadiusTexels = std::nanf(""); }, "soft.poissonRadiusTexels");
}

TEST(SoftSettingsTest, JsonRoundTripsAndNamesBadFields)
{
    ShadowSettings s;
    s.directional.filter = ShadowFilter::PCSS;
    s.local.filter = ShadowFilter::Poisson;
    s.soft = {2.0f, 0.5f, 32, 64, 2.0f, 40.0f, 3.5f, Toggle::Off};
    const ShadowSettings back = parseShadowSettings(toJson(s), "test");
    EXPECT_EQ(back.soft.diskRotation, Toggle::Off);
    EXPECT_EQ(back.directional.filter, ShadowFilter::PCSS);
    EXPECT_EQ(back.local.filter, ShadowFilter::Poisson);
    EXPECT_EQ(back.soft.blockerSearchScale, 2.0f);
    EXPECT_EQ(back.soft.penumbraScale, 0.5f);
    EXPECT_EQ(back.soft.blockerSamples, 32u);
    EXPECT_EQ(back.soft.filterSamples, 64u);
    EXPECT_EQ(back.soft.minPenumbraTexels, 2.0f);
    EXPECT_EQ(back.soft.maxPenumbraTexels, 40.0f);
    EXPECT_EQ(back.soft.poissonRadiusTexels, 3.5f);
    try {
        parseShadowSettings(R"({"soft": {"filterSamples": 48}})", "s.json");
        ADD_FAILURE();
    } catch (const rhi::Error& e) {
        EXPECT_STREQ(e.what(), "s.json: soft.filterSamples: 48 is out of range, allowed 16, 32, 64");
    }
    EXPECT_THROW(parseShadowSettings(R"({"soft": {"samples": 16}})", "s.json"), rhi::Error);
}

TEST(SoftSettingsTest, FilterNamesOnTheCommandLine)
{
    EXPECT_EQ(filterFromCommandName("hard"), ShadowFilter::PCF2x2);
    EXPECT_EQ(filterFromCommandName("pcf7"), ShadowFilter::PCF7x7);
    EXPECT_EQ(filterFromCommandName("pcss"), ShadowFilter::PCSS);
    EXPECT_EQ(filterFromCommandName("pcf2x2"), std::nullopt);
    EXPECT_TRUE(isSoftFilter(ShadowFilter::Poisson));
    EXPECT_FALSE(isSoftFilter(ShadowFilter::PCF7x7));
}

TEST(SoftSettingsTest, CascadeDataCarriesTheTexelSize)
{
    const CascadeData d = cascadeData({glm::vec3(0.0f), 10.0f}, 0.05f, ShadowFilter::PCSS, 15.0f);
    EXPECT_EQ(d.texelWorldSize, 0.05f);
    EXPECT_NEAR(d.normalBias, 0.05f * 1.4142136f, 1e-7f); // the soft filters keep the 2x2's one-texel normal offset
}

ShadowCamera cameraAt(glm::vec3 position)
{
    ShadowCamera camera = testing::uprightCamera(position, glm::vec3(0.2f, -0.3f, -1.0f));
    camera.fovY = 1.0f;
    camera.aspect = 16.0f / 9.0f;
    camera.nearPlane = 0.1f;
    camera.farPlane = 200.0f;
    return camera;
}

TEST(SoftPlannerTest, EveryCascadeMapsDepthToWorldDistanceAndKeepsTheLightTexelGrid)
{
    const std::vector<Bounds> casters{{{-3, 0, -8}, {3, 2, -4}}};
    std::vector<DirectionalShadowLightInput> lights(1);
    lights[0].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    lights[0].filter = ShadowFilter::PCSS;
    lights[0].angularDiameter = 3.0f;
    ShadowSettings settings;
    settings.maxDistance = 40.0f;
    for (const rhi::Conventions& conventions : allConventions()) {
        SCOPED_TRACE(conventionName(conventions));
        const DirectionalShadowPlan a =
            planDirectionalShadows(settings, conventions, cameraAt({0, 2, 5}), lights, casters);
        const DirectionalShadowPlan b =
            planDirectionalShadows(settings, conventions, cameraAt({0.37f, 2, 4.1f}), lights, casters);
        EXPECT_EQ(a.uniforms.lights[0].shadowFilter, ShadowFilter::PCSS);
        EXPECT_NEAR(a.uniforms.lights[0].tanHalfAngle, std::tan(0.0261799f), 1e-6f);
        EXPECT_EQ(a.uniforms.lights[0].filterBiasScale, 1.0f); // PCSS's normal offset is the 2x2's, the atlas's default
        for (const DirectionalCascadePlan& cascade : a.lights[0].cascades) {
            const glm::vec2 row = a.uniforms.tileSoft[cascade.tile].depthRow;
            // Depths at the near and the far plane are the light-space depth range apart in world units, measured from
            // the casters' top (the box's corner nearest the light).
            const float nearDepth = conventions.windowDepth(cascade.fit.projection, 0.0f);
            const float farDepth =
                conventions.windowDepth(cascade.fit.projection, cascade.fit.farDepth - cascade.fit.nearDepth);
            const float top = lightSpaceBounds(cascade.fit.basis, casters[0]).min.z;
            EXPECT_NEAR(orthographicDistanceFromNear(nearDepth, row), cascade.fit.nearDepth - top, 1e-3f);
            EXPECT_NEAR(orthographicDistanceFromNear(farDepth, row) - orthographicDistanceFromNear(nearDepth, row),
                        cascade.fit.farDepth - cascade.fit.nearDepth, 1e-2f);
        }
        // A world point's texel in the light's grid (tile texel - tile origin + anchor) is the same from either camera.
        const glm::vec3 point{0.4f, 0.0f, -6.0f};
        for (std::uint32_t c = 0; c < 2; ++c) {
            const auto lightTexel = [&](const DirectionalShadowPlan& plan) {
                const DirectionalCascadePlan& cascade = plan.lights[0].cascades[c];
                const glm::vec4 atlas = cascade.worldToAtlas * glm::vec4(point, 1.0f);
                const glm::vec2 texel = glm::vec2(atlas) * static_cast<float>(plan.atlas.atlasSize());
                return glm::floor(texel - glm::vec2(plan.atlas.tileOffset(cascade.tile)) +
                                  plan.uniforms.tileSoft[cascade.tile].lightTexelAnchor + 0.5f);
            };
            EXPECT_EQ(lightTexel(a), lightTexel(b)) << "cascade " << c;
            // The blocker search's receiver depth does not follow the camera either.
            const auto fromTop = [&](const DirectionalShadowPlan& plan) {
                const DirectionalCascadePlan& cascade = plan.lights[0].cascades[c];
                return orthographicDistanceFromNear((cascade.worldToAtlas * glm::vec4(point, 1.0f)).z,
                                                    plan.uniforms.tileSoft[cascade.tile].depthRow);
            };
            EXPECT_NEAR(fromTop(a), fromTop(b), 1e-3f) << "cascade " << c;
        }
    }
}

TEST(SoftPlannerTest, LocalLightsCarryTheirFilterRadiusAndNearPlane)
{
    const std::vector<Bounds> casters{{{-1, 0, -1}, {1, 1, 1}}};
    SpotShadowInput spot;
    spot.position = {0, 5, 0};
    spot.filter = ShadowFilter::PCSS;
    spot.sourceRadius = 0.2f;
    PointShadowInput point;
    point.position = {0, 4, 0};
    point.filter = ShadowFilter::Poisson;
    ShadowSettings settings;
    for (const PointShadowMode mode : {PointShadowMode::Atlas, PointShadowMode::CubeMap}) {
        settings.local.pointMode = mode;
        const LocalShadowPlan plan = planLocalShadows(settings, allConventions()[0], cameraAt({0, 2, 8}),
                                                      std::span(&spot, 1), std::span(&point, 1), casters);
        const int tile = plan.spotTiles[0];
        ASSERT_GE(tile, 0);
        EXPECT_EQ(plan.tileData[tile].shadowFilter, ShadowFilter::PCSS);
        // lightTexels = R x tile size x P[0][0] / 2.
        const float p00 = 1.0f / std::tan(spot.outerAngle);
        EXPECT_NEAR(plan.tileData[tile].soft.lightTexels, 0.2f * plan.tiles[tile].viewport.width * p00 / 2.0f, 1e-3f);
        EXPECT_NEAR(plan.tileData[tile].soft.nearPlane, 0.01f * spot.range, 1e-6f);
        if (mode == PointShadowMode::CubeMap)
            EXPECT_EQ(plan.uniforms.cubes[0].shadowFilter, ShadowFilter::Poisson);
        else
            EXPECT_EQ(plan.tileData[plan.pointShadows[0]].shadowFilter, ShadowFilter::Poisson);
    }
}

} // namespace
} // namespace penumbra::shadows
