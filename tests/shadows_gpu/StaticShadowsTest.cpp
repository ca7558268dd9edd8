// Static shadow maps (shadows::StaticShadowSettings) in every configuration: drawn once and kept while nothing static
// changes, drawn again for exactly the light whose view or casters changed, on demand only when asked, mixed with the
// realtime shadows beyond the shadow distance and for lights without realtime tiles.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"
#include "StaticShadowScenes.hpp"

#include "penumbra/truth/ShadowTruth.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"
#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

using shadows::ShadowFilter;

// The static map updates of boxesUnderASpot(), by light.
const std::vector<std::string> kSunMap{"directional light 0 ('sun')"};
const std::vector<std::string> kLampMap{"spot light 0 ('lamp')"};
const std::vector<std::string> kBothMaps{kSunMap[0], kLampMap[0]};
const std::vector<std::string> kNoMap;

std::vector<std::string> lightsOf(const std::vector<std::string>& updates)
{
    std::vector<std::string> lights;
    for (const std::string& update : updates)
        lights.push_back(update.substr(0, update.find(':')));
    return lights;
}

class StaticShadowsTest : public GpuTest {
protected:
    rhi::Image read(const render::SceneRenderer& renderer) { return rhi::readTexture(*device, renderer.litImage()); }

    std::string picture(const rhi::Image& image, const std::string& name)
    {
        return savePicture(image, "static-shadows-" + name + "-" + configuration());
    }
};

TEST_F(StaticShadowsTest, StaticMapsAreDrawnOnceWhileTheDynamicBallMoves)
{
    scene::Scene scene = scenes::makeTownScene();
    const render::FrameDesc frame = staticMapsFrame();
    render::SceneRenderer cached(*device, scene);
    // A renderer asked to draw every map afresh each frame, for the same scene: what the kept maps must give.
    render::FrameDesc freshFrame = frame;
    freshFrame.shadows.staticMaps.update = shadows::StaticShadowUpdate::OnDemand;
    render::SceneRenderer fresh(*device, scene);
    for (int k = 0; k < 3; ++k) {
        const render::FrameStats stats = cached.render(scene.camera, frame);
        if (k == 0) {
            EXPECT_EQ(lightsOf(stats.staticMapUpdates), std::vector<std::string>{"directional light 0 ('sun')"});
            EXPECT_EQ(stats.staticCasterDraws, 65u) << "the ground and 64 buildings, not the ball";
        } else {
            EXPECT_TRUE(stats.staticMapUpdates.empty()) << stats.staticMapUpdates.front();
            EXPECT_EQ(stats.staticCasterDraws, 0u);
        }
        EXPECT_GT(stats.casterDraws, 0u);
        const rhi::Image kept = read(cached);
        fresh.requestStaticShadowUpdate();
        EXPECT_EQ(fresh.render(scene.camera, freshFrame).staticCasterDraws, 65u);
        const rhi::Image drawn = read(fresh);
        EXPECT_LE(differingShare(kept, drawn, 1), 0.001)
            << "frame " << k << ": " << picture(kept, "kept") << " vs " << picture(drawn, "fresh");
        moveObject(scene, "ball", {3.0f, 0.0f, -4.0f});
    }
}

TEST_F(StaticShadowsTest, RealtimeDynamicCastersOnlyGiveTheSamePictureWhenNothingMoves)
{
    const scene::Scene scene = scenes::makeTownScene();
    render::FrameDesc frame = staticMapsFrame();
    render::SceneRenderer renderer(*device, scene);
    const render::FrameStats allStats = renderer.render(scene.camera, frame);
    const rhi::Image a = read(renderer);
    frame.shadows.staticMaps.realtimeCasters = shadows::RealtimeCasters::Dynamic;
    renderer.render(scene.camera, frame);
    // From the second frame on, the realtime tiles' static depth comes from their caches.
    const render::FrameStats dynamicStats = renderer.render(scene.camera, frame);
    EXPECT_LE(dynamicStats.casterDraws, frame.shadows.directional.cascadeCount) << "the ball alone, once per cascade";
    EXPECT_EQ(dynamicStats.staticCasterDraws, 0u);
    EXPECT_GT(allStats.casterDraws, dynamicStats.casterDraws);
    const rhi::Image d = read(renderer);
    const double share = differingShare(a, d, 1);
    std::printf("[ static   ] %s realtime dynamic casters only vs all: %.4f%% of pixels differ by more than 1/255\n",
                configuration().c_str(), 100.0 * share);
    EXPECT_LE(share, 0.001) << picture(a, "all-casters") << " vs " << picture(d, "dynamic-casters");
}

TEST_F(StaticShadowsTest, AChangeDrawsExactlyTheMapsItTouches)
{
    scene::Scene scene = boxesUnderASpot();
    render::FrameDesc frame = staticMapsFrame();
    render::SceneRenderer renderer(*device, scene);
    const auto updated = [&] { return lightsOf(renderer.render(scene.camera, frame).staticMapUpdates); };
    EXPECT_EQ(updated(), kBothMaps);
    EXPECT_EQ(updated(), kNoMap);
    moveObject(scene, "c", {0.0f, 0.0f, -1.0f}); // outside the lamp's cone
    EXPECT_EQ(updated(), kSunMap);
    moveObject(scene, "a", {0.3f, 0.0f, 0.0f});
    EXPECT_EQ(updated(), kBothMaps);
    scene.spotLights[0].range = 9.0f;
    EXPECT_EQ(updated(), kLampMap);
    scene.lights[0].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.4f));
    EXPECT_EQ(updated(), kSunMap);
    scene.spotLights[0].slopeScaleBias = 2.0f;
    EXPECT_EQ(updated(), kLampMap);
    frame.shadows.staticMaps.localAtlasSize = 256;
    EXPECT_EQ(updated(), kLampMap);
    EXPECT_EQ(updated(), kNoMap);

    // On demand, nothing is drawn until asked, whatever moves.
    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::OnDemand;
    moveObject(scene, "a", {0.3f, 0.0f, 0.0f});
    EXPECT_EQ(updated(), kNoMap);
    EXPECT_EQ(updated(), kNoMap);
    renderer.requestStaticShadowUpdate();
    EXPECT_EQ(updated(), kBothMaps);
    EXPECT_EQ(updated(), kNoMap);
}

bool hasStaticMap(const render::SceneRenderer& renderer, shadows::LightKind kind)
{
    const std::vector<shadows::StaticShadowMap>& maps = renderer.staticPlan().maps;
    return std::any_of(maps.begin(), maps.end(), [&](const shadows::StaticShadowMap& m) { return m.kind == kind; });
}

// Each light in a mode of its own (scene::LightShadowUpdate) under settings that keep no static maps: the sun on
// demand, the lamp on change, a bulb every frame (no static map at all).
TEST_F(StaticShadowsTest, EachLightKeepsItsMapInItsOwnUpdateMode)
{
    scene::Scene scene = boxesUnderASpot();
    scene.lights[0].shadowUpdate = shadows::StaticShadowUpdate::OnDemand;
    scene.spotLights[0].shadowUpdate = shadows::StaticShadowUpdate::OnChange;
    scene.pointLights.push_back({.name = "bulb",
                                 .intensity = 10.0f,
                                 .position = {3.0f, 2.5f, 1.0f},
                                 .range = 8.0f,
                                 .shadowUpdate = shadows::StaticShadowUpdate::EveryFrame});
    const scene::Scene first = scene;
    render::FrameDesc frame = staticMapsFrame(shadows::StaticShadowUpdate::EveryFrame);
    render::SceneRenderer renderer(*device, scene);
    const auto updated = [&] { return lightsOf(renderer.render(scene.camera, frame).staticMapUpdates); };
    EXPECT_EQ(updated(), kBothMaps);
    EXPECT_FALSE(hasStaticMap(renderer, shadows::LightKind::Point)) << "the bulb draws every frame";
    const rhi::Image mixed = read(renderer);
    EXPECT_EQ(updated(), kNoMap);
    moveObject(scene, "a", {0.3f, 0.0f, 0.0f}); // in the lamp's cone and the sun's view
    EXPECT_EQ(updated(), kLampMap);
    scene.lights[0].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.4f));
    EXPECT_EQ(updated(), kNoMap);
    renderer.requestStaticShadowUpdate();
    EXPECT_EQ(updated(), kBothMaps);
    EXPECT_EQ(updated(), kNoMap);

    // The scene as at first, the sun and the lamp on change as the settings now say, the bulb still every frame:
    // both maps drawn again, the first picture again.
    scene.objects.at(scene.findObject("a").value()) = first.objects.at(first.findObject("a").value());
    ++scene.revision;
    scene.lights[0] = first.lights[0];
    scene.lights[0].shadowUpdate = std::nullopt;
    scene.spotLights[0].shadowUpdate = std::nullopt;
    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::OnChange;
    EXPECT_EQ(updated(), kBothMaps);
    EXPECT_FALSE(hasStaticMap(renderer, shadows::LightKind::Point));
    const rhi::Image again = read(renderer);
    EXPECT_LE(differingShare(mixed, again, 1), 0.001)
        << picture(mixed, "mixed-modes") << " vs " << picture(again, "on-change");
    // The bulb's six tiles reshape the static local atlas: the lamp's tile moves with them.
    scene.pointLights[0].shadowUpdate = std::nullopt;
    EXPECT_EQ(updated(), (std::vector<std::string>{kLampMap[0], "point light 0 ('bulb')"}));
}

// Over the pixels both visibility views decide: how many `b` has in penumbra (neither fully lit nor fully shadowed),
// and how much shadow (sum of 1 - visibility) it has.
struct SoftShadowSummary {
    std::size_t penumbra = 0;
    double shadow = 0.0;
};

SoftShadowSummary softSummary(const rhi::Image& a, const rhi::Image& b)
{
    SoftShadowSummary summary;
    for (std::uint32_t y = 0; y < kStaticHeight; ++y)
        for (std::uint32_t x = 0; x < kStaticWidth; ++x) {
            const Rgba p = pixel(a, x, y);
            const Rgba q = pixel(b, x, y);
            if (p[3] < 128 || q[3] < 128)
                continue;
            summary.penumbra += q[0] >= 8 && q[0] <= 247 ? 1 : 0;
            summary.shadow += 1.0 - q[0] / 255.0;
        }
    return summary;
}

// A light whose shadow comes from its static map alone (the shadow distance ends before the camera sees anything)
// has the soft shadow of its realtime tiles: PCSS for the sun, the Poisson disk for the lamp. The static maps' texels
// are not the cascades' (the lamp's are the size of its realtime tile's, as the Poisson disk's radius is in texels), so
// the disks' noise falls elsewhere: the pictures are compared by how much shadow they hold
// (within 10%) and how many penumbra pixels (within a factor of 1.6); a hard-filtered static map has less than half
// the penumbra, which is what the bounds tell apart.
TEST_F(StaticShadowsTest, StaticMapsTakeTheLightsSoftFilter)
{
    scene::Scene scene = boxesUnderASpot();
    scene.lights[0].angularDiameter = 20.0f;
    // Behind box "a", so its shadow falls towards the camera.
    scene.spotLights[0].position = {-3.0f, 3.0f, -3.0f};
    scene.spotLights[0].direction = glm::normalize(glm::vec3(-3.0f, 0.0f, 1.0f) - scene.spotLights[0].position);
    scene.spotLights[0].sourceRadius = 0.5f;
    render::SceneRenderer renderer(*device, scene);
    const auto view = [&](scene::LightRef light, float maxDistance, shadows::StaticShadowUpdate update) {
        render::FrameDesc frame = staticMapsFrame(update);
        frame.shadows.maxDistance = maxDistance;
        frame.visibilityOf = light;
        // The Poisson disk's radius is in texels: the lamp's static tile has the texels of its realtime one.
        frame.shadows.staticMaps.localAtlasSize = frame.shadows.local.atlasSize;
        frame.shadows.soft.poissonRadiusTexels = 8.0f;
        renderer.render(scene.camera, frame);
        return rhi::readTexture(*device, renderer.visibilityImage());
    };
    struct Case {
        scene::LightRef light;
        std::optional<ShadowFilter>* filter;
        ShadowFilter soft;
    };
    for (const Case& c :
         {Case{{scene::LightKind::Directional, 0}, &scene.lights[0].shadowFilter, ShadowFilter::PCSS},
          Case{{scene::LightKind::Spot, 0}, &scene.spotLights[0].shadowFilter, ShadowFilter::Poisson}}) {
        *c.filter = c.soft;
        const rhi::Image realtime = view(c.light, 100.0f, shadows::StaticShadowUpdate::EveryFrame);
        const rhi::Image fromStatic = view(c.light, 0.01f, shadows::StaticShadowUpdate::OnChange);
        *c.filter = ShadowFilter::PCF2x2;
        const rhi::Image hard = view(c.light, 0.01f, shadows::StaticShadowUpdate::OnChange);
        *c.filter = std::nullopt;
        const SoftShadowSummary r = softSummary(fromStatic, realtime);
        const SoftShadowSummary st = softSummary(realtime, fromStatic);
        const SoftShadowSummary h = softSummary(realtime, hard);
        const std::string name(shadows::shadowFilters()[std::size_t(c.soft)].command);
        std::printf("[ static   ] %s %s, %s: penumbra pixels realtime %zu, static %zu, hard static %zu; shadow %.1f, "
                    "%.1f, %.1f\n",
                    configuration().c_str(), scene::lightKindName(c.light.kind), name.c_str(), r.penumbra, st.penumbra,
                    h.penumbra, r.shadow, st.shadow, h.shadow);
        const std::string pictures =
            picture(realtime, name + "-realtime") + " vs " + picture(fromStatic, name + "-static");
        EXPECT_GT(r.penumbra, 20u) << pictures;
        EXPECT_NEAR(st.shadow, r.shadow, 0.1 * r.shadow) << pictures;
        EXPECT_GE(double(st.penumbra), r.penumbra / 1.6) << pictures;
        EXPECT_LE(double(st.penumbra), r.penumbra * 1.6) << pictures;
        EXPECT_LT(2 * h.penumbra, r.penumbra) << picture(hard, name + "-hard-static");
    }
}

double linear(std::uint8_t encoded)
{
    const double c = encoded / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The lit pass mixes as static_shadows.glsl says: attenuation = mix(1, min(realtime faded, static), strength), so the
// picture is linear in the sun's shadow strength wherever its shadow comes from: at strength 0.5 every pixel is the
// mean of strengths 0 and 1 in linear light, near the camera (realtime and static), in the distance fade and beyond
// the shadow distance (static alone), within the rounding of 8-bit sRGB.
TEST_F(StaticShadowsTest, TheLightsStrengthMixesTheStaticAndRealtimeShadow)
{
    scene::Scene scene = boxesUnderASpot();
    render::FrameDesc frame = staticMapsFrame();
    frame.shadows.maxDistance = 11.0f; // the far boxes' shadows lie in the fade and beyond
    render::SceneRenderer renderer(*device, scene);
    const auto lit = [&](float strength) {
        scene.lights[0].shadowStrength = strength;
        renderer.render(scene.camera, frame);
        return read(renderer);
    };
    const rhi::Image none = lit(0.0f);
    const rhi::Image full = lit(1.0f);
    const rhi::Image half = lit(0.5f);
    const truth::RayCaster cameraRays(scene, truth::RayKind::Camera);
    const truth::CpuGBuffer gbuffer = truth::traceGBuffer(scene, cameraRays, scene.camera, kStaticWidth, kStaticHeight);
    double worst = 0.0;
    std::size_t shadowed = 0;
    std::size_t shadowedBeyond = 0; // past the start of the distance fade: the static map's share grows to all
    for (std::size_t i = 0; i < half.bytes.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) {
            const double a = linear(std::to_integer<std::uint8_t>(none.bytes[i + c]));
            const double b = linear(std::to_integer<std::uint8_t>(full.bytes[i + c]));
            const double m = linear(std::to_integer<std::uint8_t>(half.bytes[i + c]));
            // One 8-bit step around each value, in linear light.
            const double slack = linear(std::min(255, std::to_integer<int>(half.bytes[i + c]) + 1)) - m;
            worst = std::max(worst, std::abs(m - 0.5 * (a + b)) / std::max(slack, 1e-6));
            const bool inShadow = c == 0 && a - b > 0.05;
            shadowed += inShadow ? 1 : 0;
            const truth::GBufferSample& sample =
                gbuffer.at(std::uint32_t(i / 4 % kStaticWidth), std::uint32_t(i / 4 / kStaticWidth));
            shadowedBeyond += inShadow && sample.object != truth::kNoObject &&
                                      sample.viewDepth > frame.shadows.maxDistance * (1.0f - frame.shadows.distanceFade)
                                  ? 1
                                  : 0;
        }
    std::printf("[ static   ] %s strength 0.5 against the mean of 0 and 1: worst %.2f 8-bit steps, %zu shadowed "
                "pixels, %zu in the distance fade or beyond\n",
                configuration().c_str(), worst, shadowed, shadowedBeyond);
    EXPECT_GT(shadowed, 50u) << picture(full, "strength-1");
    EXPECT_GT(shadowedBeyond, 10u) << picture(full, "strength-1");
    EXPECT_LE(worst, 1.5) << picture(none, "strength-0") << " " << picture(half, "strength-half") << " "
                          << picture(full, "strength-1");
}

// The sun's visibility view at view depths beyond the shadow distance: pixels some shadow map decides, and of those
// the shadowed ones; with static maps it agrees with the ray cast, without them nothing decides.
TEST_F(StaticShadowsTest, BeyondTheShadowDistanceTheStaticMapContinuesTheShadowAsTheRayCastDoes)
{
    const scene::Scene scene = scenes::makeTownScene();
    render::FrameDesc frame = staticMapsFrame();
    frame.shadows.maxDistance = 40.0f;
    const scene::LightRef sun{scene::LightKind::Directional, 0};
    frame.visibilityOf = sun;
    const truth::RayCaster cameraRays(scene, truth::RayKind::Camera);
    const truth::CpuGBuffer gbuffer = truth::traceGBuffer(scene, cameraRays, scene.camera, kStaticWidth, kStaticHeight);
    render::SceneRenderer renderer(*device, scene);
    struct FarShadow {
        std::size_t decided = 0;
        std::size_t shadowed = 0;
    };
    // A pixel whose 3 x 3 neighbourhood lies beyond: the rasterizer and the ray cast may see different sides of
    // an edge.
    const auto far = [&](std::uint32_t x, std::uint32_t y) {
        for (std::uint32_t v = std::max(y, 1u) - 1; v <= std::min(y + 1, kStaticHeight - 1); ++v)
            for (std::uint32_t u = std::max(x, 1u) - 1; u <= std::min(x + 1, kStaticWidth - 1); ++u)
                if (gbuffer.at(u, v).object == truth::kNoObject || gbuffer.at(u, v).viewDepth < 50.0f)
                    return false;
        return true;
    };
    const auto farShadow = [&](const rhi::Image& view) {
        FarShadow result;
        for (std::uint32_t y = 0; y < kStaticHeight; ++y)
            for (std::uint32_t x = 0; x < kStaticWidth; ++x) {
                if (!far(x, y))
                    continue;
                const Rgba p = pixel(view, x, y);
                result.decided += p[3] >= 128 ? 1 : 0;
                result.shadowed += p[3] >= 128 && p[0] < 128 ? 1 : 0;
            }
        return result;
    };

    renderer.render(scene.camera, frame);
    const rhi::Image cachedView = rhi::readTexture(*device, renderer.visibilityImage());
    const FarShadow cached = farShadow(cachedView);
    EXPECT_GT(cached.decided, std::size_t(kStaticWidth) * kStaticHeight / 10);
    EXPECT_GT(cached.shadowed, cached.decided / 10) << "the buildings' far shadows";
    const truth::RayCaster shadowRays(scene);
    const truth::LightTruthTrace truth =
        truth::traceLightTruth(scene, shadowRays, gbuffer, renderer.planShadows(scene.camera, frame), frame.shadows,
                               sun);
    const truth::TruthComparison f =
        truth::compareLightTruth(truth, shadowRays, gbuffer, truth::renderedVisibility(cachedView));
    std::printf("[ truth    ] %s town with static maps: lit %zu of %zu right, shadowed %zu of %zu right\n",
                configuration().c_str(), f.lit.right, f.lit.compared, f.shadowed.right, f.shadowed.compared);
    EXPECT_GE(f.lit.share(), 0.99);
    EXPECT_GE(f.shadowed.share(), 0.99);

    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::EveryFrame;
    renderer.render(scene.camera, frame);
    EXPECT_EQ(farShadow(rhi::readTexture(*device, renderer.visibilityImage())).decided, 0u)
        << "realtime shadows end at the shadow distance";
}

TEST_F(StaticShadowsTest, ALightWithoutRealtimeTilesKeepsItsStaticShadow)
{
    scene::Scene scene = boxesUnderASpot();
    scene.lights.clear();
    scene.spotLights.clear();
    // Three point lights need 18 tiles; a 256^2 realtime atlas whose tiles may not go below 128^2 holds 4, so none
    // of them keeps realtime tiles.
    for (int i = 0; i < 3; ++i)
        scene.pointLights.push_back({.name = "bulb " + std::to_string(i + 1),
                                     .intensity = 20.0f,
                                     .position = {-3.0f + 3.0f * static_cast<float>(i), 2.5f, 1.0f},
                                     .range = 10.0f});
    render::FrameDesc frame = staticMapsFrame();
    frame.shadows.local.atlasSize = 256;
    frame.shadows.local.minTileResolution = 128;
    frame.visibilityOf = scene::LightRef{scene::LightKind::Point, 2};
    render::SceneRenderer renderer(*device, scene);
    const auto shadowed = [&](std::vector<std::string>& notes) {
        notes = renderer.render(scene.camera, frame).notes;
        const rhi::Image view = rhi::readTexture(*device, renderer.visibilityImage());
        std::size_t count = 0;
        for (std::uint32_t y = 0; y < kStaticHeight; ++y)
            for (std::uint32_t x = 0; x < kStaticWidth; ++x)
                count += pixel(view, x, y)[3] >= 128 && pixel(view, x, y)[0] < 128 ? 1 : 0;
        return count;
    };
    std::vector<std::string> notes;
    EXPECT_GT(shadowed(notes), 30u);
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
        return n.find("point light 2 ('bulb 3') has static shadows only") != std::string::npos;
    }));
    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::EveryFrame;
    EXPECT_EQ(shadowed(notes), 0u);
}

std::filesystem::path bakeFolder(const std::string& name)
{
    const char* root = std::getenv("PENUMBRA_TEST_OUTPUT");
    return std::filesystem::path(root ? root : "test-output") / ("bake-" + name + "-" + configuration());
}

// One renderer bakes, then loads the bake back under a scene and settings changed in turn. (A bake made on each
// configuration and loaded on every other: StaticShadowParity.)
TEST_F(StaticShadowsTest, StaleMismatchedAndTruncatedBakesAreRefusedByName)
{
    scene::Scene scene = boxesUnderASpot();
    render::FrameDesc frame = staticMapsFrame();
    const std::filesystem::path folder = bakeFolder("refused");
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, frame);
    shadows::writeStaticShadowBake(folder, renderer.bakeStaticShadows(configuration()));
    const shadows::StaticShadowBake bake = shadows::readStaticShadowBake(folder);
    ASSERT_EQ(bake.maps.size(), 2u);
    EXPECT_EQ(bake.objects.size(), 4u);
    renderer.useBakedShadows(bake);
    const auto renderWith = [&](const render::FrameDesc& f) {
        return errorOf([&] { renderer.render(scene.camera, f); });
    };
    EXPECT_EQ(renderWith(frame), "(no error)");
    render::FrameDesc smaller = frame;
    smaller.shadows.staticMaps.localAtlasSize = 256;
    const std::string resized = renderWith(smaller);
    EXPECT_NE(resized.find("was baked as 1 tiles of 512 texels, the settings give 1 of 256"), std::string::npos)
        << resized;
    moveObject(scene, "a", {0.5f, 0.0f, 0.0f});
    // The sun's map holds every static caster, so it is the first to be stale.
    const std::string stale = renderWith(frame);
    EXPECT_NE(stale.find("directional light 0 ('sun') is stale"), std::string::npos) << stale;
    // A light the bake lacks is named before any stale map.
    scene.spotLights.push_back(scene.spotLights[0]);
    scene.spotLights[1].name = "second lamp";
    const std::string missing = renderWith(frame);
    EXPECT_NE(missing.find("no map for spot light 1"), std::string::npos) << missing;

    // A cut depth file and a cut manifest.
    const std::filesystem::path exr = folder / "spot-0.exr";
    std::filesystem::resize_file(exr, std::filesystem::file_size(exr) / 2);
    EXPECT_NE(errorOf([&] { shadows::readStaticShadowBake(folder); }).find("spot-0.exr"), std::string::npos);
    const std::filesystem::path manifest = folder / "manifest.json";
    std::filesystem::resize_file(manifest, std::filesystem::file_size(manifest) / 2);
    EXPECT_NE(errorOf([&] { shadows::readStaticShadowBake(folder); }).find("manifest.json: not valid JSON"),
              std::string::npos);
    std::filesystem::remove_all(folder);
    EXPECT_NE(errorOf([&] { shadows::readStaticShadowBake(folder); }).find("cannot open the bake's manifest"),
              std::string::npos);
}

} // namespace
} // namespace penumbra::testing
