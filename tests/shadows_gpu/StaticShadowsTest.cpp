// Static shadow maps (shadows::StaticShadowSettings) in every configuration: drawn once and kept while nothing static
// changes, drawn again for exactly the light whose view or casters changed, on demand only when asked, mixed with the
// realtime shadows beyond the shadow distance and for lights without realtime tiles.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/ShadowTruth.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"
#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scene/TestScenes.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kWidth = 256;
constexpr std::uint32_t kHeight = 144;

render::FrameDesc cachedFrame(shadows::StaticShadowUpdate update = shadows::StaticShadowUpdate::OnChange)
{
    render::FrameDesc frame;
    frame.width = kWidth;
    frame.height = kHeight;
    frame.shadows.staticMaps.update = update;
    frame.shadows.staticMaps.directionalAtlasSize = 2048;
    frame.shadows.staticMaps.otherAtlasSize = 1024;
    return frame;
}

void moveObject(scene::Scene& scene, const std::string& name, glm::vec3 offset)
{
    scene::Object& object = scene.objects.at(scene.findObject(name).value());
    object.transform = glm::translate(glm::mat4(1.0f), offset) * object.transform;
    object.worldBounds = scene.meshOf(object).bounds.transformed(object.transform);
}

// Pixels whose channels differ by more than 1 step, out of all.
double differingShare(const rhi::Image& a, const rhi::Image& b)
{
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.bytes.size(); i += 4) {
        bool differs = false;
        for (std::size_t c = 0; c < 3; ++c)
            differs |= std::abs(std::to_integer<int>(a.bytes[i + c]) - std::to_integer<int>(b.bytes[i + c])) > 1;
        differing += differs ? 1 : 0;
    }
    return static_cast<double>(differing) / static_cast<double>(a.bytes.size() / 4);
}

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
    scene::Scene scene = scene::makeTownScene();
    const render::FrameDesc frame = cachedFrame();
    render::SceneRenderer cached(*device, scene);
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
        // A renderer of its own draws every map afresh for the same scene: what the kept maps must give.
        const rhi::Image kept = read(cached);
        const rhi::Image fresh = renderLit(*device, scene, frame);
        EXPECT_LE(differingShare(kept, fresh), 0.001)
            << "frame " << k << ": " << picture(kept, "kept") << " vs " << picture(fresh, "fresh");
        moveObject(scene, "ball", {3.0f, 0.0f, -4.0f});
    }
}

TEST_F(StaticShadowsTest, RealtimeDynamicCastersOnlyGiveTheSamePictureWhenNothingMoves)
{
    const scene::Scene scene = scene::makeTownScene();
    render::FrameDesc frame = cachedFrame();
    render::SceneRenderer all(*device, scene);
    const render::FrameStats allStats = all.render(scene.camera, frame);
    frame.shadows.staticMaps.realtimeCasters = shadows::RealtimeCasters::Dynamic;
    render::SceneRenderer dynamic(*device, scene);
    dynamic.render(scene.camera, frame);
    // From the second frame on, the realtime tiles' static depth comes from their caches.
    const render::FrameStats dynamicStats = dynamic.render(scene.camera, frame);
    EXPECT_LE(dynamicStats.casterDraws, frame.shadows.directional.cascadeCount) << "the ball alone, once per cascade";
    EXPECT_EQ(dynamicStats.staticCasterDraws, 0u);
    EXPECT_GT(allStats.casterDraws, dynamicStats.casterDraws);
    const rhi::Image a = read(all);
    const rhi::Image d = read(dynamic);
    const double share = differingShare(a, d);
    std::printf("[ static   ] %s realtime dynamic casters only vs all: %.4f%% of pixels differ by more than 1/255\n",
                configuration().c_str(), 100.0 * share);
    EXPECT_LE(share, 0.001) << picture(a, "all-casters") << " vs " << picture(d, "dynamic-casters");
}

// Ground, three boxes and a spot light over box "a"; the sun sees them all.
scene::Scene boxesUnderASpot()
{
    scene::Scene s;
    const std::uint32_t grey = s.addMaterial({.name = "grey", .baseColor = {0.7f, 0.7f, 0.7f, 1.0f}});
    s.addObject("ground", s.addMesh(scene::makeBox({12.0f, 0.1f, 12.0f})), grey,
                glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}));
    const std::uint32_t box = s.addMesh(scene::makeBox({0.5f, 0.5f, 0.5f}));
    s.addObject("a", box, grey, glm::translate(glm::mat4(1.0f), {-3.0f, 0.5f, 0.0f}));
    s.addObject("b", box, grey, glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f}));
    s.addObject("c", box, grey, glm::translate(glm::mat4(1.0f), {6.0f, 0.5f, 3.0f}));
    s.lights = {{.name = "sun", .intensity = 1.5f, .direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f))}};
    s.spotLights = {{.name = "lamp",
                     .intensity = 40.0f,
                     .position = {-3.0f, 4.0f, 0.0f},
                     .direction = {0.0f, -1.0f, 0.0f},
                     .range = 8.0f,
                     .innerAngle = 0.4f,
                     .outerAngle = 0.5f}};
    s.camera = scene::lookAt({0.0f, 8.0f, 10.0f}, {0.0f, 0.0f, 0.0f}, 0.9f);
    return s;
}

TEST_F(StaticShadowsTest, AChangeDrawsExactlyTheMapsItTouches)
{
    scene::Scene scene = boxesUnderASpot();
    render::FrameDesc frame = cachedFrame();
    render::SceneRenderer renderer(*device, scene);
    const auto updated = [&] { return lightsOf(renderer.render(scene.camera, frame).staticMapUpdates); };
    const std::vector<std::string> sun{"directional light 0 ('sun')"};
    const std::vector<std::string> lamp{"spot light 0 ('lamp')"};
    const std::vector<std::string> both{sun[0], lamp[0]};
    const std::vector<std::string> none;
    EXPECT_EQ(updated(), both);
    EXPECT_EQ(updated(), none);
    moveObject(scene, "c", {0.0f, 0.0f, -1.0f}); // outside the lamp's cone
    EXPECT_EQ(updated(), sun);
    moveObject(scene, "a", {0.3f, 0.0f, 0.0f});
    EXPECT_EQ(updated(), both);
    scene.spotLights[0].range = 9.0f;
    EXPECT_EQ(updated(), lamp);
    scene.lights[0].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.4f));
    EXPECT_EQ(updated(), sun);
    scene.spotLights[0].slopeScaleBias = 2.0f;
    EXPECT_EQ(updated(), lamp);
    frame.shadows.staticMaps.otherAtlasSize = 512;
    EXPECT_EQ(updated(), lamp);
    EXPECT_EQ(updated(), none);

    // On demand, nothing is drawn until asked, whatever moves.
    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::OnDemand;
    moveObject(scene, "a", {0.3f, 0.0f, 0.0f});
    EXPECT_EQ(updated(), none);
    EXPECT_EQ(updated(), none);
    renderer.requestStaticShadowUpdate();
    EXPECT_EQ(updated(), both);
    EXPECT_EQ(updated(), none);
}

// The visibility view of the sun at view depths beyond the shadow distance: pixels some shadow map decides, and of
// those the shadowed ones.
struct FarShadow {
    std::size_t decided = 0;
    std::size_t shadowed = 0;
};

TEST_F(StaticShadowsTest, BeyondTheShadowDistanceTheStaticMapContinuesTheShadow)
{
    const scene::Scene scene = scene::makeTownScene();
    render::FrameDesc frame = cachedFrame();
    frame.shadows.maxDistance = 40.0f;
    frame.visibilityOf = scene::LightRef{scene::LightKind::Directional, 0};
    const auto farShadow = [&](const render::FrameDesc& f) {
        render::SceneRenderer renderer(*device, scene);
        renderer.render(scene.camera, f);
        const rhi::Image view = rhi::readTexture(*device, renderer.visibilityImage());
        const scene::RayCaster cameraRays(scene, scene::RayKind::Camera);
        const scene::CpuGBuffer gbuffer = scene::traceGBuffer(scene, cameraRays, scene.camera, kWidth, kHeight);
        FarShadow result;
        for (std::uint32_t y = 0; y < kHeight; ++y)
            for (std::uint32_t x = 0; x < kWidth; ++x) {
                const scene::GBufferSample& sample = gbuffer.at(x, y);
                if (sample.object == scene::kNoObject || sample.viewDepth < 50.0f)
                    continue;
                const Rgba p = pixel(view, x, y);
                result.decided += p[3] >= 128 ? 1 : 0;
                result.shadowed += p[3] >= 128 && p[0] < 128 ? 1 : 0;
            }
        return result;
    };
    const FarShadow cached = farShadow(frame);
    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::EveryFrame;
    const FarShadow realtime = farShadow(frame);
    EXPECT_EQ(realtime.decided, 0u) << "realtime shadows end at the shadow distance";
    EXPECT_GT(cached.decided, std::size_t(kWidth) * kHeight / 10);
    EXPECT_GT(cached.shadowed, cached.decided / 10) << "the buildings' far shadows";
}

TEST_F(StaticShadowsTest, BakedShadowsBeyondTheShadowDistanceAgreeWithTheRayCast)
{
    const scene::Scene scene = scene::makeTownScene();
    render::FrameDesc frame = cachedFrame();
    frame.shadows.maxDistance = 40.0f;
    const scene::LightRef sun{scene::LightKind::Directional, 0};
    frame.visibilityOf = sun;
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, frame);
    const scene::RenderedVisibility mask =
        render::renderedVisibility(rhi::readTexture(*device, renderer.visibilityImage()));
    const scene::RayCaster cameraRays(scene, scene::RayKind::Camera);
    const scene::RayCaster shadowRays(scene);
    const scene::CpuGBuffer gbuffer = scene::traceGBuffer(scene, cameraRays, scene.camera, kWidth, kHeight);
    const render::LightTruthTrace truth = render::traceLightTruth(
        scene, shadowRays, gbuffer, renderer.planShadows(scene.camera, frame), frame.shadows, sun);
    const scene::TruthComparison f = scene::compareWithTruth(gbuffer, truth.visibility, mask, truth.shadowEdges);
    std::printf("[ truth    ] %s town with static maps: lit %zu of %zu right, shadowed %zu of %zu right\n",
                configuration().c_str(), f.lit.right, f.lit.compared, f.shadowed.right, f.shadowed.compared);
    EXPECT_GE(f.lit.share(), 0.99);
    EXPECT_GE(f.shadowed.share(), 0.99);
}

TEST_F(StaticShadowsTest, ALightWithoutRealtimeTilesKeepsItsStaticShadow)
{
    scene::Scene scene = boxesUnderASpot();
    scene.lights.clear();
    scene.spotLights.clear();
    // Three point lights need 18 tiles of the 16 the realtime atlas has: the third gets none.
    for (int i = 0; i < 3; ++i)
        scene.pointLights.push_back({.name = "bulb " + std::to_string(i + 1),
                                     .intensity = 20.0f,
                                     .position = {-3.0f + 3.0f * static_cast<float>(i), 2.5f, 1.0f},
                                     .range = 10.0f});
    render::FrameDesc frame = cachedFrame();
    frame.visibilityOf = scene::LightRef{scene::LightKind::Point, 2};
    const auto decided = [&](const render::FrameDesc& f, std::vector<std::string>& notes) {
        render::SceneRenderer renderer(*device, scene);
        notes = renderer.render(scene.camera, f).notes;
        const rhi::Image view = rhi::readTexture(*device, renderer.visibilityImage());
        std::size_t shadowed = 0;
        for (std::uint32_t y = 0; y < kHeight; ++y)
            for (std::uint32_t x = 0; x < kWidth; ++x)
                shadowed += pixel(view, x, y)[3] >= 128 && pixel(view, x, y)[0] < 128 ? 1 : 0;
        return shadowed;
    };
    std::vector<std::string> notes;
    EXPECT_GT(decided(frame, notes), 100u);
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
        return n.find("point light 2 ('bulb 3') has static shadows only") != std::string::npos;
    }));
    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::EveryFrame;
    EXPECT_EQ(decided(frame, notes), 0u);
}

std::filesystem::path bakeFolder(const std::string& name)
{
    const char* root = std::getenv("PENUMBRA_TEST_OUTPUT");
    return std::filesystem::path(root ? root : "test-output") / ("bake-" + name + "-" + configuration());
}

std::string errorOf(const std::function<void()>& f)
{
    try {
        f();
    } catch (const rhi::Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST_F(StaticShadowsTest, ABakeLoadsOnEveryConfigurationWithTheSameShadows)
{
    const scene::Scene scene = boxesUnderASpot();
    const render::FrameDesc frame = cachedFrame();
    render::SceneRenderer baker(*device, scene);
    baker.render(scene.camera, frame);
    const rhi::Image live = read(baker);
    const std::filesystem::path folder = bakeFolder("round-trip");
    shadows::writeStaticShadowBake(folder, baker.bakeStaticShadows(configuration()));
    const shadows::StaticShadowBake bake = shadows::readStaticShadowBake(folder);
    ASSERT_EQ(bake.maps.size(), 2u);
    EXPECT_EQ(bake.objects.size(), 4u);
    reportSkipped(forEachConfiguration([&](rhi::Device& loader, const std::string& other) {
        SCOPED_TRACE("loaded on " + other);
        render::SceneRenderer renderer(loader, scene);
        renderer.useBakedShadows(bake);
        const render::FrameStats stats = renderer.render(scene.camera, frame);
        EXPECT_EQ(stats.staticCasterDraws, 0u) << "a bake draws no static caster";
        EXPECT_EQ(stats.staticMapUpdates.size(), 2u);
        const rhi::Image loaded = rhi::readTexture(loader, renderer.litImage());
        EXPECT_LE(differingShare(live, loaded), 0.001)
            << picture(live, "baked-here") << " vs " << picture(loaded, "loaded-on-" + other);
    }));
}

TEST_F(StaticShadowsTest, StaleMismatchedAndTruncatedBakesAreRefusedByName)
{
    scene::Scene scene = boxesUnderASpot();
    render::FrameDesc frame = cachedFrame();
    const std::filesystem::path folder = bakeFolder("refused");
    {
        render::SceneRenderer baker(*device, scene);
        baker.render(scene.camera, frame);
        shadows::writeStaticShadowBake(folder, baker.bakeStaticShadows(configuration()));
    }
    const shadows::StaticShadowBake bake = shadows::readStaticShadowBake(folder);
    const auto renderWith = [&](const scene::Scene& s, const render::FrameDesc& f) {
        return errorOf([&] {
            render::SceneRenderer renderer(*device, s);
            renderer.useBakedShadows(bake);
            renderer.render(s.camera, f);
        });
    };
    EXPECT_EQ(renderWith(scene, frame), "(no error)");
    scene::Scene moved = scene;
    moveObject(moved, "a", {0.5f, 0.0f, 0.0f});
    // The sun's map holds every static caster, so it is the first to be stale.
    const std::string stale = renderWith(moved, frame);
    EXPECT_NE(stale.find("directional light 0 ('sun') is stale"), std::string::npos) << stale;
    render::FrameDesc smaller = frame;
    smaller.shadows.staticMaps.otherAtlasSize = 512;
    const std::string resized = renderWith(scene, smaller);
    EXPECT_NE(resized.find("was baked as 1 tiles of 1024 texels, the settings give 1 of 512"), std::string::npos)
        << resized;
    scene::Scene more = scene;
    more.spotLights.push_back(more.spotLights[0]);
    more.spotLights[1].name = "second lamp";
    const std::string missing = renderWith(more, frame);
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
