// Base colour textures from glTF reach the lit pass (colour, sRGB-decoded) and the alpha of masked casters
// in both passes: an opaque texture casts a shadow, a transparent one neither shows nor casts.
#include "GltfBuilder.hpp"
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/gltf/GltfLoader.hpp"
#include "penumbra/render/SceneRenderer.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kTexturedWidth = 320;
constexpr std::uint32_t kTexturedHeight = 180;

class TexturedMaterialTest : public GpuTest {
protected:
    // A 3 x 3 panel at y = 2 over a ground plane, its MASK material white with a 2 x 2 texture of `texel`.
    scene::Scene panelScene(std::array<std::uint8_t, 4> texel)
    {
        GltfBuilder b;
        std::vector<std::uint8_t> rgba;
        for (int i = 0; i < 4; ++i)
            rgba.insert(rgba.end(), texel.begin(), texel.end());
        const int image = b.addPngImage(2, 2, rgba);
        const int texture = b.add("textures", {{"source", image}});
        const int ground = b.add("materials", {{"name", "ground"}});
        const int panel = b.add("materials", {{"name", "panel"},
                                              {"alphaMode", "MASK"},
                                              {"alphaCutoff", 0.5},
                                              {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}});
        b.addRoot(b.add("nodes", {{"name", "ground"},
                                  {"mesh", addCubeMesh(b, "ground", ground)},
                                  {"translation", {0, -0.1, 0}},
                                  {"scale", {8, 0.1, 8}}}));
        b.addRoot(b.add("nodes", {{"name", "panel"},
                                  {"mesh", addCubeMesh(b, "panel", panel)},
                                  {"translation", {0, 2, 0}},
                                  {"scale", {1.5, 0.05, 1.5}}}));
        const std::filesystem::path path =
            std::filesystem::temp_directory_path() / ("penumbra-textured-" + configuration() + ".glb");
        b.writeGlb(path);
        scene::Scene scene = gltf::loadGltf(path).scene;
        std::filesystem::remove(path);
        scene.lights = {{.name = "sun", .intensity = 2.0f, .direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.0f))}};
        scene.camera = scene::lookAt({0.0f, 6.0f, 8.0f}, {0.0f, 0.0f, 0.0f}, 1.0f);
        return scene;
    }

    rhi::Image render(const scene::Scene& scene)
    {
        render::FrameDesc frame;
        frame.width = kTexturedWidth;
        frame.height = kTexturedHeight;
        return renderLit(*device, scene, frame);
    }

    glm::uvec2 pixelOf(const scene::Scene& scene, glm::vec3 world) const
    {
        return testing::pixelOf(*device, scene.camera, kTexturedWidth, kTexturedHeight, world);
    }
};

TEST_F(TexturedMaterialTest, TextureColourAndAlphaReachTheLitAndCasterPasses)
{
    const scene::Scene opaque = panelScene({230, 20, 20, 255});
    const scene::Scene transparent = panelScene({230, 20, 20, 0});
    ASSERT_EQ(opaque.textures.size(), 1u);
    const rhi::Image withPanel = render(opaque);
    const rhi::Image withoutPanel = render(transparent);

    // The panel's top, and ground in the panel's shadow (the sun leans towards +x) seen past its edge.
    const glm::uvec2 top = pixelOf(opaque, {0.0f, 2.05f, 0.0f});
    const glm::uvec2 shadowed = pixelOf(opaque, {2.2f, 0.0f, 0.0f});
    const Rgba panel = pixel(withPanel, top.x, top.y);
    std::printf("[ texture  ] %s: panel %s, ground in its shadow %.1f with the opaque texture, %.1f with the "
                "transparent one\n",
                configuration().c_str(), describe(panel).c_str(), luminance(withPanel, shadowed.x, shadowed.y),
                luminance(withoutPanel, shadowed.x, shadowed.y));
    EXPECT_GT(panel[0], 2 * panel[1]) << "the texture's red is not on the panel";
    EXPECT_GT(panel[0], 2 * panel[2]);
    const Rgba through = pixel(withoutPanel, top.x, top.y);
    EXPECT_LT(through[0], 2 * through[1]) << "a fully transparent masked panel is drawn";
    EXPECT_LT(luminance(withPanel, shadowed.x, shadowed.y), 0.6f * luminance(withoutPanel, shadowed.x, shadowed.y))
        << "the opaque texture casts no shadow, or the transparent one does";
    if (HasFailure())
        ADD_FAILURE() << savePicture(withPanel, "textured-" + configuration() + "-opaque") << ", "
                      << savePicture(withoutPanel, "textured-" + configuration() + "-transparent");
}

} // namespace
} // namespace penumbra::testing
