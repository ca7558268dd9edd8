// The render regression test: every built-in scene and the main frame variants (forward and screen-space shadows,
// MSAA 4, no depth prepass, a draw per object, the cascade and visibility views, point cube maps, soft filters,
// static maps on change with dynamic realtime casters, over two frames and restored from a bake, the reference lit
// pass) drawn small on this configuration, each output (the lit image, the atlases, the debug views) hashed and
// compared with the table committed in frame_hashes/: the pictures and atlases must stay byte-identical while the
// renderer's code is restructured. The table holds what one driver drew; on another (another Mesa, a real GPU) the
// test skips, naming both. PENUMBRA_UPDATE_FRAME_HASHES=1 writes the table of this configuration afresh instead of
// comparing.
#include "FrameHashTable.hpp"
#include "GpuTesting.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/ReferenceLitPass.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kWidth = 160;
constexpr std::uint32_t kHeight = 90;
constexpr std::uint32_t kGridCubes = 100;

using FrameChange = std::function<void(render::FrameDesc&)>;

struct Variant {
    std::string name;
    FrameChange change;
};

struct SceneFrames {
    std::string name;
    std::function<scene::Scene()> make;
    std::vector<Variant> variants; // besides "forward", the default frame
    bool referencePass = false; // the forward frame also hashes render::ReferenceLitPass's picture (penumbra bench)
};

const scene::LightRef kSpot{scene::LightKind::Spot, 0};
const scene::LightRef kPoint{scene::LightKind::Point, 0};

void soft(render::FrameDesc& frame)
{
    frame.shadows.directional.filter = shadows::ShadowFilter::PCSS;
    frame.shadows.local.filter = shadows::ShadowFilter::Poisson;
}

// Static maps kept on change, the realtime atlases drawing the dynamic casters alone over the static depth cached per
// tile.
void staticMapsWithDynamicCasters(render::FrameDesc& frame)
{
    frame.shadows.staticMaps.update = shadows::StaticShadowUpdate::OnChange;
    frame.shadows.staticMaps.realtimeCasters = shadows::RealtimeCasters::Dynamic;
    frame.shadows.staticMaps.directionalAtlasSize = 1024;
    frame.shadows.staticMaps.localAtlasSize = 512;
}

const std::vector<SceneFrames>& sceneFrames()
{
    static const std::vector<SceneFrames> scenes{
        {"shadow-test", scenes::makeShadowTestScene, {}},
        {"single-light", scenes::makeSingleLightScene, {}},
        {"mixed-lights",
         scenes::makeMixedLightsScene,
         {{"screen-space", [](render::FrameDesc& f) { f.shadowPath = render::ShadowPath::ScreenSpace; }},
          {"msaa4", [](render::FrameDesc& f) { f.msaa = 4; }},
          {"no-prepass", [](render::FrameDesc& f) { f.depthPrepass = false; }},
          {"per-object-draws", [](render::FrameDesc& f) { f.instancedDraws = false; }},
          {"views",
           [](render::FrameDesc& f) {
               f.cascadeView = true;
               f.visibilityOf = kSpot;
           }},
          {"soft", soft},
          {"static-dynamic", staticMapsWithDynamicCasters}}},
        {"point-light-room",
         scenes::makePointLightRoomScene,
         {{"cube-maps",
           [](render::FrameDesc& f) {
               f.shadows.local.pointMode = shadows::PointShadowMode::CubeMap;
               f.visibilityOf = kPoint;
           }}}},
        {"forest", scenes::makeForestScene, {}, true},
        {"contact", scenes::makeContactScene, {}},
        {"town", scenes::makeTownScene, {}},
        {"cube-grid", [] { return scenes::makeCubeGridScene(kGridCubes); }, {}},
    };
    return scenes;
}

render::FrameDesc smallFrame(const FrameChange& change)
{
    render::FrameDesc frame;
    frame.width = kWidth;
    frame.height = kHeight;
    if (change)
        change(frame);
    return frame;
}

bool hasMapOf(const shadows::StaticShadowPlan& plan, bool directional)
{
    return std::any_of(plan.maps.begin(), plan.maps.end(), [&](const shadows::StaticShadowMap& map) {
        return (map.kind == shadows::LightKind::Directional) == directional;
    });
}

// Every output the frame wrote: the lit image, the atlases and cube maps its plans draw into (an atlas no tile of
// which is used holds whatever its memory held), and the views its settings ask for.
FrameHashes outputsOf(rhi::Device& device, const render::SceneRenderer& renderer, const render::FrameDesc& frame)
{
    FrameHashes h;
    h["lit"] = hashOf(rhi::readTexture(device, renderer.litImage()));
    if (!renderer.plan().lights.empty())
        h["atlas"] = hashOf(rhi::readDepth(device, renderer.atlas().texture()));
    if (!renderer.localPlan().tiles.empty())
        h["localAtlas"] = hashOf(rhi::readDepth(device, renderer.localAtlas().texture()));
    if (!renderer.localPlan().cubes.empty()) {
        rhi::DepthImage faces;
        for (std::uint32_t layer = 0; layer < 6 * renderer.localPlan().cubes.size(); ++layer) {
            const rhi::DepthImage face = rhi::readDepth(device, renderer.shadowCubes().texture(), layer);
            faces.depth.insert(faces.depth.end(), face.depth.begin(), face.depth.end());
        }
        h["cubeMaps"] = hashOf(faces);
    }
    if (shadows::hasStaticMaps(frame.shadows) && hasMapOf(renderer.staticPlan(), true))
        h["staticAtlas"] = hashOf(rhi::readDepth(device, renderer.staticDirectionalAtlas().texture()));
    if (shadows::hasStaticMaps(frame.shadows) && hasMapOf(renderer.staticPlan(), false))
        h["staticLocalAtlas"] = hashOf(rhi::readDepth(device, renderer.staticLocalAtlas().texture()));
    if (frame.shadowPath == render::ShadowPath::ScreenSpace)
        h["screenSpaceShadows"] = hashOf(rhi::readTexture(device, renderer.screenSpaceShadowImage()));
    if (frame.cascadeView)
        h["cascadeView"] = hashOf(rhi::readTexture(device, renderer.cascadeImage()));
    if (frame.visibilityOf)
        h["visibilityView"] = hashOf(rhi::readTexture(device, renderer.visibilityImage()));
    return h;
}

// The town with static maps kept on change and the realtime atlases drawing the dynamic ball alone, over two frames:
// the second after the ball moves, its static depth from the tile caches; then the static maps baked and restored.
void addStaticFrames(rhi::Device& device, FrameTable& table)
{
    scene::Scene town = scenes::makeTownScene();
    const render::FrameDesc frame = smallFrame(staticMapsWithDynamicCasters);
    render::SceneRenderer renderer(device, town);
    renderer.render(town.camera, frame);
    table["town/static-dynamic"] = outputsOf(device, renderer, frame);
    scene::Object& ball = town.objects.at(town.findObject("ball").value());
    ball.transform = glm::translate(glm::mat4(1.0f), {3.0f, 0.0f, -4.0f}) * ball.transform;
    ball.worldBounds = town.meshOf(ball).bounds.transformed(ball.transform);
    ++town.revision;
    renderer.render(town.camera, frame);
    table["town/static-dynamic-ball-moved"] = outputsOf(device, renderer, frame);
    renderer.useBakedShadows(renderer.bakeStaticShadows(configuration()));
    renderer.render(town.camera, frame);
    table["town/static-baked"] = outputsOf(device, renderer, frame);
}

// One renderer per scene draws its frames in turn (a renderer per frame gives the same table: no frame depends on
// what the renderer drew before, which a restructuring must keep too), so that each shader is compiled once.
FrameTable renderEveryFrame(rhi::Device& device)
{
    FrameTable table;
    for (const SceneFrames& s : sceneFrames()) {
        const scene::Scene scene = s.make();
        render::SceneRenderer renderer(device, scene);
        const auto draw = [&](const std::string& variant, const render::FrameDesc& frame) {
            renderer.render(scene.camera, frame);
            table[s.name + "/" + variant] = outputsOf(device, renderer, frame);
        };
        // The reference lit pass runs in the forward frame only, after the lit pass, as penumbra bench adds it.
        std::shared_ptr<render::ReferenceLitPass> reference;
        if (s.referencePass) {
            reference = std::make_shared<render::ReferenceLitPass>(device, renderer, scene.camera, smallFrame({}));
            renderer.addTexture(std::string(render::ReferenceLitPass::kImage), reference->image());
            renderer.addTexture(std::string(render::ReferenceLitPass::kDepth), reference->depth());
            renderer.addPass(reference, render::PassPlacement::after(std::string(render::frame::kLitPass)));
        }
        draw("forward", smallFrame({}));
        if (reference) {
            table[s.name + "/forward"]["referenceLit"] = hashOf(rhi::readTexture(device, reference->image()));
            reference->setEnabled(false);
        }
        for (const Variant& v : s.variants)
            draw(v.name, smallFrame(v.change));
    }
    addStaticFrames(device, table);
    return table;
}

std::string driverOf(const rhi::Device& device)
{
    return device.capabilities().api + ", " + device.capabilities().device;
}

std::filesystem::path tablePath()
{
    return std::filesystem::path(PENUMBRA_FRAME_HASHES_DIR) / (configuration() + ".json");
}

using RenderRegressionTest = GpuTest;

TEST_F(RenderRegressionTest, EveryBuiltInSceneAndFrameVariantMatchesTheCommittedHashes)
{
    const char* update = std::getenv("PENUMBRA_UPDATE_FRAME_HASHES");
    if (update && std::string(update) == "1") {
        writeFrameHashes(tablePath(), {configuration(), driverOf(*device), renderEveryFrame(*device)});
        std::printf("[ hashes   ] wrote %s\n", tablePath().string().c_str());
        return;
    }
    const FrameHashFile committed = readFrameHashes(tablePath());
    if (committed.driver != driverOf(*device))
        GTEST_SKIP() << tablePath().string() << " was made by \"" << committed.driver << "\", this device is \""
                     << driverOf(*device) << "\": pictures may differ by driver; PENUMBRA_UPDATE_FRAME_HASHES=1 "
                     << "makes a table for it from a commit known to be right";
    const std::vector<std::string> differences = frameDifferences(committed.frames, renderEveryFrame(*device));
    std::string listed;
    for (const std::string& d : differences)
        listed += "\n  " + d;
    EXPECT_TRUE(differences.empty()) << differences.size() << " outputs differ from " << tablePath().string() << ":"
                                     << listed;
}

// One texel changed, of the lit image or of an atlas, is a difference the comparison names.
TEST_F(RenderRegressionTest, ChangedTexelCatchesFault)
{
    const scene::Scene scene = scenes::makeContactScene();
    const render::FrameDesc frame = smallFrame({});
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, frame);
    const FrameTable table{{"contact/forward", outputsOf(*device, renderer, frame)}};
    EXPECT_TRUE(frameDifferences(table, table).empty());

    rhi::Image lit = rhi::readTexture(*device, renderer.litImage());
    lit.bytes[lit.bytes.size() / 2] ^= std::byte{1};
    FrameTable changedLit = table;
    changedLit["contact/forward"]["lit"] = hashOf(lit);
    const std::vector<std::string> litDifferences = frameDifferences(table, changedLit);
    ASSERT_EQ(litDifferences.size(), 1u);
    EXPECT_NE(litDifferences[0].find("contact/forward: lit is"), std::string::npos) << litDifferences[0];

    rhi::DepthImage atlas = rhi::readDepth(*device, renderer.atlas().texture());
    float& texel = atlas.depth[atlas.depth.size() / 3];
    texel = std::nextafter(texel, 2.0f);
    FrameTable changedAtlas = table;
    changedAtlas["contact/forward"]["atlas"] = hashOf(atlas);
    const std::vector<std::string> atlasDifferences = frameDifferences(table, changedAtlas);
    ASSERT_EQ(atlasDifferences.size(), 1u);
    EXPECT_NE(atlasDifferences[0].find("contact/forward: atlas is"), std::string::npos) << atlasDifferences[0];
}

} // namespace
} // namespace penumbra::testing
