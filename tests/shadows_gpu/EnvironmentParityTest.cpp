// Image-based lighting across configurations: a grid of spheres built here (rows: silver, gold, a red dielectric;
// columns: roughness from 0.05 to 1) lit by the built-in studio environment alone, no light, through every
// configuration. The metals are no longer black, and the pictures agree; the negative control leaves the environment
// out and the metals' brightness check catches it. A white furnace checks the specular reflectance's energy.
#include "GpuTesting.hpp"
#include "ShadowScene.hpp"

#include "penumbra/parity/GoogleTest.hpp"
#include "penumbra/scene/MeshGenerators.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace penumbra {
namespace {

constexpr std::uint32_t kEnvironmentWidth = 192;
constexpr std::uint32_t kEnvironmentHeight = 144;
constexpr int kColumns = 5;
constexpr int kRows = 3;
constexpr float kCameraDistance = 7.0f;
constexpr float kFovY = 0.698132f; // 40 degrees
// Mean luma (0..255, sRGB-encoded) at the metal spheres' centres: measured 85 lit by the studio (74 before the
// specular reflectance counted multiple scattering), 45 with the ambient light alone.
constexpr float kLitMetalLuma = 60.0f;

scene::Scene sphereGrid()
{
    scene::Scene scene;
    const std::uint32_t mesh = scene.addMesh(scene::makeSphere(0.42f, 48, 24));
    const glm::vec3 bases[kRows] = {{0.95f, 0.93f, 0.88f}, {1.0f, 0.78f, 0.34f}, {0.8f, 0.1f, 0.08f}};
    for (int row = 0; row < kRows; ++row)
        for (int column = 0; column < kColumns; ++column) {
            scene::Material material;
            material.baseColor = glm::vec4(bases[row], 1.0f);
            material.metallic = row < 2 ? 1.0f : 0.0f;
            material.roughness = 0.05f + 0.95f * float(column) / float(kColumns - 1);
            const glm::vec3 centre{float(column - kColumns / 2), float(kRows / 2 - row), 0.0f};
            scene.addObject("sphere", mesh, scene.addMaterial(material), glm::translate(glm::mat4(1.0f), centre));
        }
    scene.camera = scene::lookAt({0.0f, 0.0f, kCameraDistance}, glm::vec3(0.0f), kFovY);
    return scene;
}

render::FrameDesc gridFrame(bool environment)
{
    render::FrameDesc frame;
    frame.width = kEnvironmentWidth;
    frame.height = kEnvironmentHeight;
    if (environment) {
        static const auto studio = std::make_shared<const render::EnvironmentImage>(render::studioEnvironment());
        frame.environment.image = studio;
    }
    return frame;
}

// The mean luma of 3 x 3 pixels at each metal sphere's centre.
float metalLuma(const rhi::Image& picture)
{
    const float halfHeight = kCameraDistance * std::tan(kFovY / 2.0f);
    const float halfWidth = halfHeight * float(kEnvironmentWidth) / float(kEnvironmentHeight);
    float sum = 0.0f;
    int count = 0;
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < kColumns; ++column) {
            const float x = float(column - kColumns / 2);
            const float y = float(kRows / 2 - row);
            const auto px = std::uint32_t((0.5f + 0.5f * x / halfWidth) * float(kEnvironmentWidth));
            const auto py = std::uint32_t((0.5f - 0.5f * y / halfHeight) * float(kEnvironmentHeight));
            for (std::uint32_t dy = py - 1; dy <= py + 1; ++dy)
                for (std::uint32_t dx = px - 1; dx <= px + 1; ++dx, ++count)
                    sum += testing::luminance(picture, dx, dy);
        }
    return sum / float(count);
}

const std::vector<parity::ConfigurationRun>& gridRuns()
{
    static const std::vector<parity::ConfigurationRun> runs =
        parity::renderConfigurations([](rhi::Device& device, const rhi::NamedConfiguration& configuration) {
            const apps::ShadowPictures pictures =
                apps::renderShadowScene(device, configuration.name, sphereGrid(), gridFrame(true), false);
            testing::savePicture(pictures.lit, "environment-spheres-" + configuration.name);
            return std::vector{parity::colorPicture("lit", pictures.lit)};
        });
    return runs;
}

TEST(EnvironmentParity, SphereGridLitByTheStudioAgreesEverywhere) { PENUMBRA_EXPECT_PARITY(gridRuns(), {}); }

TEST(EnvironmentParity, MetalSpheresAreNotBlack)
{
    for (const parity::ConfigurationRun& run : gridRuns()) {
        ASSERT_EQ(run.status, parity::ConfigurationRun::Status::Rendered) << run.message;
        EXPECT_GT(metalLuma(run.picture("lit").color), kLitMetalLuma) << run.name();
    }
}

// The negative control: without the environment (the ambient light alone) the same check fails.
TEST(EnvironmentParity, EnvironmentLeftOutCatchesFault)
{
    const parity::ConfigurationRun& first = gridRuns().front();
    const apps::ShadowPictures none = apps::renderShadowScene(first.name(), sphereGrid(), gridFrame(false));
    testing::savePicture(none.lit, "environment-spheres-none");
    EXPECT_LT(metalLuma(none.lit), kLitMetalLuma);
}

// A white furnace: a metal of base colour 1 in a constant environment reflects all of it at every roughness and angle
// once multiple scattering is counted (Fdez-Aguera 2019, "A Multiple-Scattering Microfacet Model for Real-Time
// Image-based Lighting", JCGT 8(1)); single scattering alone reflects A + B of it (with it alone, this picture
// measured 178 and 113 of 255 at roughness 0.5 and 1 where 188 is expected).
TEST(EnvironmentParity, WhiteMetalInAConstantEnvironmentReflectsAllOfIt)
{
    constexpr std::uint32_t kFurnaceWidth = 96, kFurnaceHeight = 48;
    constexpr float kFurnaceDistance = 4.0f, kFurnaceRadius = 0.8f, kFurnaceRadiance = 0.5f;
    scene::Scene furnace;
    const std::uint32_t mesh = furnace.addMesh(scene::makeSphere(kFurnaceRadius, 48, 24));
    const float roughnesses[2] = {0.5f, 1.0f};
    for (int i = 0; i < 2; ++i) {
        scene::Material material;
        material.baseColor = glm::vec4(1.0f);
        material.metallic = 1.0f;
        material.roughness = roughnesses[i];
        furnace.addObject("white metal", mesh, furnace.addMaterial(material),
                          glm::translate(glm::mat4(1.0f), glm::vec3(i == 0 ? -1.0f : 1.0f, 0.0f, 0.0f)));
    }
    furnace.camera = scene::lookAt({0.0f, 0.0f, kFurnaceDistance}, glm::vec3(0.0f), kFovY);
    render::FrameDesc frame;
    frame.width = kFurnaceWidth;
    frame.height = kFurnaceHeight;
    auto constant = std::make_shared<render::EnvironmentImage>();
    constant->width = 64;
    constant->height = 32;
    constant->texels.assign(64 * 32, glm::vec3(kFurnaceRadiance));
    frame.environment.image = constant;
    const apps::ShadowPictures pictures = apps::renderShadowScene(gridRuns().front().name(), furnace, frame);
    const std::string saved = testing::savePicture(pictures.lit, "environment-white-furnace");
    // 0.5 encoded by the sRGB curve (IEC 61966-2-1): 1.055 * 0.5^(1 / 2.4) - 0.055 = 0.7354, 187.5 of 255.
    constexpr int kEncoded = 188;
    const float halfHeight = kFurnaceDistance * std::tan(kFovY / 2.0f);
    const float halfWidth = halfHeight * float(kFurnaceWidth) / float(kFurnaceHeight);
    for (int i = 0; i < 2; ++i)
        for (const glm::vec2 offset :
             {glm::vec2(0.0f), glm::vec2(0.5f, 0.0f), glm::vec2(0.0f, 0.5f), glm::vec2(-0.5f, -0.4f)}) {
            const glm::vec2 at = glm::vec2(i == 0 ? -1.0f : 1.0f, 0.0f) + offset * kFurnaceRadius;
            const auto x = std::uint32_t((0.5f + 0.5f * at.x / halfWidth) * float(kFurnaceWidth));
            const auto y = std::uint32_t((0.5f - 0.5f * at.y / halfHeight) * float(kFurnaceHeight));
            const testing::Rgba c = testing::pixel(pictures.lit, x, y);
            for (int channel = 0; channel < 3; ++channel)
                EXPECT_NEAR(int(c[std::size_t(channel)]), kEncoded, 3)
                    << "roughness " << roughnesses[i] << " at (" << x << ", " << y << "): " << testing::describe(c)
                    << ", " << saved;
        }
}

} // namespace
} // namespace penumbra
