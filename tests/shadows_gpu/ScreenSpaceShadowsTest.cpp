// The screen-space shadow path (FrameDesc::shadowPath): the collection after the depth prepass puts a shadow where
// the forward path does, on every configuration (no backend-dependent flip of screen coordinates), and the lit image
// it gives is the forward path's: at most 0.01% of pixels differ by more than 1/255, on the built-in scenes and the
// forest, single-sampled and, with the edge fallback (DirectionalShadowSource::ScreenSpaceEdges), with 4x MSAA.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kScreenSpaceWidth = 320;
constexpr std::uint32_t kScreenSpaceHeight = 180;
// The acceptance: 0.01% of the picture, 5 of 320 x 180's 57 600 pixels.
constexpr std::size_t kMostDiffering = std::size_t(kScreenSpaceWidth) * kScreenSpaceHeight / 10000;

// A ground plane seen from straight above, +x to the right and -z up the picture (SceneOptions' look-down camera),
// and one small floating cube whose shadow, the only one, falls in the top-left quadrant of the picture.
scene::Scene cornerMarkerScene()
{
    scene::Scene scene;
    const std::uint32_t ground = scene.addMesh(scene::makePlane(20.0f));
    const std::uint32_t cube = scene.addMesh(scene::makeBox(glm::vec3(0.4f)));
    const std::uint32_t grey = scene.addMaterial({.name = "grey", .baseColor = {0.7f, 0.7f, 0.7f, 1.0f}});
    scene.addObject("ground", ground, grey, glm::mat4(1.0f));
    scene.addObject("marker", cube, grey, glm::translate(glm::mat4(1.0f), glm::vec3(-4.5f, 1.5f, -3.0f)));
    // Tilted towards +x and +z: the shadow lands 0.75 right of and 0.45 below the cube in the picture.
    scene.lights = {{.name = "sun", .intensity = 2.0f, .direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.3f))}};
    scene.camera = scene::lookAt({0.0f, 10.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.9f, {0.0f, 0.0f, -1.0f});
    scene.validate();
    return scene;
}

// An RGBA32F image's floats.
std::vector<float> texels(const rhi::Image& image)
{
    std::vector<float> values(image.bytes.size() / sizeof(float));
    std::memcpy(values.data(), image.bytes.data(), image.bytes.size());
    return values;
}

// The screen-space shadow texture's first three channels (lights 0, 1, 2) as an RGBA8 picture.
rhi::Image shadowPicture(const std::vector<float>& shadows, std::uint32_t width, std::uint32_t height)
{
    rhi::Image picture{width, height, rhi::Format::RGBA8, std::vector<std::byte>(shadows.size())};
    for (std::size_t i = 0; i < shadows.size(); ++i)
        picture.bytes[i] = i % 4 == 3
                               ? std::byte{255}
                               : static_cast<std::byte>(std::lround(std::clamp(shadows[i], 0.0f, 1.0f) * 255.0f));
    return picture;
}

class ScreenSpaceShadowsTest : public GpuTest {
protected:
    // Trilinear without anisotropy, as DepthPrepassTest: the forest's leaves cost lavapipe 50 times more with it.
    render::FrameDesc frame(render::ShadowPath path, std::uint32_t msaa = 1) const
    {
        render::FrameDesc f = litFrame(kScreenSpaceWidth, kScreenSpaceHeight, true, msaa);
        f.maxAnisotropy = 1.0f;
        f.shadowPath = path;
        return f;
    }

    // Forward and screen-space lit images of `scene` from one renderer (their pipelines compiled once): the pixels
    // that differ by more than 1/255. The pictures and the shadow texture are saved.
    std::size_t pathDifference(const scene::Scene& scene, const std::string& name, std::uint32_t msaa = 1)
    {
        render::SceneRenderer renderer(*device, scene);
        renderer.render(scene.camera, frame(render::ShadowPath::Forward, msaa));
        const rhi::Image forward = rhi::readTexture(*device, renderer.litImage());
        renderer.render(scene.camera, frame(render::ShadowPath::ScreenSpace, msaa));
        const rhi::Image collected = rhi::readTexture(*device, renderer.litImage());
        const std::vector<float> shadows = texels(rhi::readTexture(*device, renderer.screenSpaceShadowImage()));
        EXPECT_TRUE(std::any_of(shadows.begin(), shadows.end(), [](float s) { return s < 0.5f; }))
            << name << ": the screen-space shadow texture holds no shadow";
        savePicture(forward, fmt::format("{}/screen-space-{}-forward", configuration(), name));
        savePicture(collected, fmt::format("{}/screen-space-{}-collected", configuration(), name));
        savePicture(shadowPicture(shadows, forward.width, forward.height),
                    fmt::format("{}/screen-space-{}-shadow-texture", configuration(), name));
        const std::size_t differing = differingPixels(forward, collected, 1);
        RecordProperty("differingPixels", static_cast<int>(differing));
        return differing;
    }
};

TEST_F(ScreenSpaceShadowsTest, MarkerShadowLandsInItsCorner)
{
    const scene::Scene scene = cornerMarkerScene();
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, frame(render::ShadowPath::ScreenSpace));
    const rhi::Image mask = rhi::readTexture(*device, renderer.screenSpaceShadowImage());
    const rhi::Image lit = rhi::readTexture(*device, renderer.litImage());
    const rhi::Image unshadowed = renderLit(*device, withoutShadows(scene), frame(render::ShadowPath::ScreenSpace));
    savePicture(lit, configuration() + "/screen-space-marker");
    ASSERT_EQ(mask.format, rhi::Format::RGBA32F);
    const std::vector<float> shadows = texels(mask);
    std::size_t maskedInCorner = 0, maskedElsewhere = 0, darkInCorner = 0, darkElsewhere = 0;
    for (std::uint32_t y = 0; y < kScreenSpaceHeight; ++y)
        for (std::uint32_t x = 0; x < kScreenSpaceWidth; ++x) {
            const bool corner = x < kScreenSpaceWidth / 2 && y < kScreenSpaceHeight / 2;
            const bool masked = shadows[(std::size_t(y) * kScreenSpaceWidth + x) * 4] < 0.5f;
            const bool dark = luminance(lit, x, y) + 20.0f < luminance(unshadowed, x, y);
            (corner ? maskedInCorner : maskedElsewhere) += masked ? 1 : 0;
            (corner ? darkInCorner : darkElsewhere) += dark ? 1 : 0;
        }
    EXPECT_GT(maskedInCorner, 20u) << "the marker's shadow is not in the top-left quadrant of the shadow texture";
    EXPECT_EQ(maskedElsewhere, 0u) << "shadow outside the top-left quadrant of the shadow texture";
    EXPECT_GT(darkInCorner, 20u) << "the marker's shadow is not in the top-left quadrant of the lit image";
    EXPECT_EQ(darkElsewhere, 0u) << "shadow outside the top-left quadrant of the lit image";
}

TEST_F(ScreenSpaceShadowsTest, NeedsTheDepthPrepass)
{
    const scene::Scene scene = cornerMarkerScene();
    render::SceneRenderer renderer(*device, scene);
    render::FrameDesc f = frame(render::ShadowPath::ScreenSpace);
    f.depthPrepass = false;
    EXPECT_NE(errorOf([&] { renderer.render(scene.camera, f); }).find("needs FrameDesc::depthPrepass"),
              std::string::npos);
}

TEST_F(ScreenSpaceShadowsTest, SameLitImageAsForwardOnTheTestScene)
{
    EXPECT_LE(pathDifference(scenes::makeShadowTestScene(), "test"), kMostDiffering);
}

TEST_F(ScreenSpaceShadowsTest, SameLitImageAsForwardOnTheMixedScene)
{
    EXPECT_LE(pathDifference(scenes::makeMixedLightsScene(), "mixed"), kMostDiffering);
}

// PCSS with a 10 degree sun: the soft filters' receiver plane comes from the prepass's derivatives.
TEST_F(ScreenSpaceShadowsTest, SameLitImageAsForwardOnTheContactScene)
{
    EXPECT_LE(pathDifference(scenes::makeContactScene(), "contact"), kMostDiffering);
}

TEST_F(ScreenSpaceShadowsTest, SameLitImageAsForwardInTheForest)
{
    EXPECT_LE(pathDifference(scenes::makeForestScene(), "forest"), kMostDiffering);
}

// 4x MSAA over the test scene's silhouettes against shadowed ground: a per-pixel collection gives edge pixels the
// shadow of the surface behind; the edge fallback evaluates them forward (README, "Screen-space shadows and MSAA").
TEST_F(ScreenSpaceShadowsTest, MsaaEdgesKeepTheirOwnShadow)
{
    EXPECT_LE(pathDifference(scenes::makeShadowTestScene(), "test-msaa4", 4), kMostDiffering);
}

} // namespace
} // namespace penumbra::testing
