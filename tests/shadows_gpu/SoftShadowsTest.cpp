// Soft shadows against a ray-traced area light (scene::AreaLightTruth) on the contact scene: PCSS beats every fixed
// filter, its penumbrae widen away from the pole's foot as the true ones do, nothing leaks at the contact; a frame
// of hard and soft lights; stability under sub-texel camera moves; cube maps against atlas tiles.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/render/ShadowTruth.hpp"
#include "penumbra/render/SoftShadowTruth.hpp"
#include "penumbra/scene/AreaLightTruth.hpp"
#include "penumbra/scene/RayCaster.hpp"
#include "penumbra/scene/TestScenes.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace penumbra::testing {
namespace {

using scene::LightKind;
using scene::LightRef;
using shadows::ShadowFilter;

constexpr std::uint32_t kSize = 192;

// The contact scene lit by one light of `kind`: its sun, or a spot or point light of radius 0.15 up and to the
// left of the pole, so every shadow still runs along +x from the pole's foot.
scene::Scene contactScene(LightKind kind, ShadowFilter filter)
{
    scene::Scene scene = scene::makeContactScene();
    const auto value = static_cast<std::int32_t>(filter);
    if (kind == LightKind::Directional) {
        scene.lights[0].shadowFilter = value;
        return scene;
    }
    scene.lights.clear();
    const glm::vec3 position{-2.0f, 3.5f, 0.0f};
    if (kind == LightKind::Spot)
        scene.spotLights.push_back({.name = "spot", .intensity = 20.0f, .position = position,
                                    .direction = glm::normalize(glm::vec3(1.8f, -3.5f, 0.0f)), .range = 15.0f,
                                    .innerAngle = 0.7f, .outerAngle = 1.0f, .sourceRadius = 0.15f,
                                    .shadowFilter = value});
    else
        scene.pointLights.push_back({.name = "point", .intensity = 20.0f, .position = position, .range = 15.0f,
                                     .sourceRadius = 0.15f, .shadowFilter = value});
    scene.validate();
    return scene;
}

render::FrameDesc softFrame(LightRef light)
{
    render::FrameDesc frame;
    frame.width = kSize;
    frame.height = kSize;
    frame.shadows.maxDistance = 20.0f;
    frame.shadows.directional.cascadeCount = 1;
    frame.shadows.directional.atlasSize = 2048;
    frame.shadows.other.atlasSize = 2048;
    frame.visibilityOf = light;
    return frame;
}

class SoftShadowsTest : public GpuTest {
public:
    scene::RenderedVisibility visibility(const scene::Scene& scene, const render::FrameDesc& frame)
    {
        render::SceneRenderer renderer(*device, scene);
        renderer.render(scene.camera, frame);
        return render::renderedVisibility(rhi::readTexture(*device, renderer.visibilityImage()));
    }

    // The area light's ray cast of the scene's pixels (256 rays each).
    static scene::SoftVisibilityMap truth(const scene::Scene& scene, LightRef light)
    {
        const scene::RayCaster cameraRays(scene, scene::RayKind::Camera);
        const scene::RayCaster shadowRays(scene);
        const scene::CpuGBuffer gbuffer = scene::traceGBuffer(scene, cameraRays, scene.camera, kSize, kSize);
        return scene::traceAreaLightVisibility(scene, shadowRays, gbuffer, render::areaLightOf(scene, light));
    }
};

LightRef firstLight(LightKind kind) { return {kind, 0}; }

// The penumbra's width (pixels with visibility strictly between 5% and 95%) down picture column `x` over the rows
// where the ground lies within `halfSpan` of z = 0, both sides of the shadow together.
template <typename At>
int penumbraWidth(At visibilityAt, std::uint32_t x, std::uint32_t firstRow, std::uint32_t lastRow)
{
    int width = 0;
    for (std::uint32_t y = firstRow; y <= lastRow; ++y) {
        const float v = visibilityAt(x, y);
        width += v > 0.05f && v < 0.95f;
    }
    return width;
}

TEST_F(SoftShadowsTest, PcssErrorIsAtMostHalfTheBestFixedFilters)
{
    for (const LightKind kind : {LightKind::Directional, LightKind::Spot, LightKind::Point}) {
        SCOPED_TRACE(scene::lightKindName(kind));
        const LightRef light = firstLight(kind);
        const scene::SoftVisibilityMap area = truth(contactScene(kind, ShadowFilter::PCSS), light);
        const auto error = [&](ShadowFilter filter, float poissonRadius) {
            render::FrameDesc frame = softFrame(light);
            frame.shadows.soft.poissonRadiusTexels = poissonRadius;
            return scene::compareSoftVisibility(area, visibility(contactScene(kind, filter), frame));
        };
        const scene::SoftTruthFigures pcss = error(ShadowFilter::PCSS, 2.5f);
        double bestFixed = error(ShadowFilter::PCF7x7, 2.5f).meanAbsError;
        std::string fixed = fmt::format("pcf7 {:.4f}", bestFixed);
        for (const float radius : {2.0f, 4.0f, 8.0f, 16.0f}) {
            const double e = error(ShadowFilter::Poisson, radius).meanAbsError;
            fixed += fmt::format(", poisson r{} {:.4f}", radius, e);
            bestFixed = std::min(bestFixed, e);
        }
        ASSERT_GT(pcss.penumbraPixels, 200u);
        EXPECT_LE(pcss.meanAbsError, 0.5 * bestFixed) << "pcss " << pcss.meanAbsError << "; " << fixed;
        std::printf("%s: %zu penumbra pixels, pcss %.4f; %s\n", scene::lightKindName(kind), pcss.penumbraPixels,
                    pcss.meanAbsError, fixed.c_str());
    }
}

TEST_F(SoftShadowsTest, PenumbraeWidenAwayFromTheContactAsTheAreaLightsDo)
{
    const LightRef sun = firstLight(LightKind::Directional);
    const scene::Scene scene = contactScene(LightKind::Directional, ShadowFilter::PCSS);
    const scene::SoftVisibilityMap area = truth(scene, sun);
    const scene::RenderedVisibility pcss = visibility(scene, softFrame(sun));
    const std::uint32_t firstRow = pixelOf(*device, scene.camera, kSize, kSize, {1.0f, 0.0f, -0.9f}).y;
    const std::uint32_t lastRow = pixelOf(*device, scene.camera, kSize, kSize, {1.0f, 0.0f, 0.9f}).y;
    std::vector<int> widths;
    for (const float height : {0.75f, 1.5f, 2.5f}) {
        // The pole's point at height h shadows the ground at x = h.
        const std::uint32_t x = pixelOf(*device, scene.camera, kSize, kSize, {height, 0.0f, 0.0f}).x;
        const int expected = penumbraWidth([&](std::uint32_t px, std::uint32_t py) { return area.at(px, py); }, x,
                                           firstRow, lastRow);
        const int rendered = penumbraWidth(
            [&](std::uint32_t px, std::uint32_t py) { return pcss.lit[std::size_t(py) * kSize + px]; }, x, firstRow,
            lastRow);
        EXPECT_GT(expected, 2) << "at x = " << height;
        EXPECT_NEAR(rendered, expected, 0.25 * expected) << "penumbra width in pixels at x = " << height;
        std::printf("x = %.2f: ray-traced %d px, pcss %d px\n", height, expected, rendered);
        widths.push_back(rendered);
    }
    EXPECT_LT(widths[0], widths[1]);
    EXPECT_LT(widths[1], widths[2]);
}

TEST_F(SoftShadowsTest, NoLightLeaksAtTheContact)
{
    for (const LightKind kind : {LightKind::Directional, LightKind::Spot, LightKind::Point}) {
        SCOPED_TRACE(scene::lightKindName(kind));
        const scene::Scene scene = contactScene(kind, ShadowFilter::PCSS);
        const scene::SoftVisibilityMap area = truth(scene, firstLight(kind));
        const scene::RenderedVisibility pcss = visibility(scene, softFrame(firstLight(kind)));
        // Right behind the pole's foot, in its umbra.
        for (const float x : {0.14f, 0.2f, 0.3f}) {
            const glm::uvec2 p = pixelOf(*device, scene.camera, kSize, kSize, {x, 0.0f, 0.0f});
            ASSERT_LT(area.at(p.x, p.y), 0.05f) << "x = " << x;
            EXPECT_LT(pcss.lit[std::size_t(p.y) * kSize + p.x], 0.1f) << "light leaks at x = " << x;
        }
    }
}

// Share of decided pixels strictly between lit and shadowed.
double softShare(const scene::RenderedVisibility& v)
{
    std::size_t soft = 0, decided = 0;
    for (std::size_t i = 0; i < v.lit.size(); ++i) {
        decided += v.decided[i];
        soft += v.decided[i] && v.lit[i] > 0.05f && v.lit[i] < 0.95f;
    }
    return decided == 0 ? 0.0 : double(soft) / double(decided);
}

TEST_F(SoftShadowsTest, HardTentPoissonAndPcssLightsShareOneFrame)
{
    scene::Scene scene = contactScene(LightKind::Directional, ShadowFilter::PCSS);
    scene.lights.push_back({.name = "hard sun", .intensity = 1.0f,
                            .direction = glm::normalize(glm::vec3(-1.0f, -1.5f, 0.5f)),
                            .shadowFilter = static_cast<std::int32_t>(ShadowFilter::PCF2x2)});
    scene.spotLights.push_back({.name = "tent spot", .intensity = 10.0f, .position = {2.0f, 4.0f, 2.0f},
                                .direction = glm::normalize(glm::vec3(-0.5f, -1.0f, -0.5f)), .range = 12.0f,
                                .innerAngle = 0.6f, .outerAngle = 0.9f,
                                .shadowFilter = static_cast<std::int32_t>(ShadowFilter::PCF5x5)});
    scene.pointLights.push_back({.name = "poisson point", .intensity = 10.0f, .position = {-1.0f, 3.0f, -1.5f},
                                 .range = 12.0f, .sourceRadius = 0.2f,
                                 .shadowFilter = static_cast<std::int32_t>(ShadowFilter::Poisson)});
    scene.validate();
    const double pcssShare = softShare(visibility(scene, softFrame({LightKind::Directional, 0})));
    const double hardShare = softShare(visibility(scene, softFrame({LightKind::Directional, 1})));
    const double tentShare = softShare(visibility(scene, softFrame({LightKind::Spot, 0})));
    const double poissonShare = softShare(visibility(scene, softFrame({LightKind::Point, 0})));
    std::printf("soft pixel shares: pcss %.4f, hard %.4f, tent %.4f, poisson %.4f\n", pcssShare, hardShare, tentShare,
                poissonShare);
    EXPECT_GT(pcssShare, 3.0 * hardShare);
    EXPECT_GT(tentShare, hardShare);
    EXPECT_GT(poissonShare, 0.0);
    render::FrameDesc lit = softFrame({});
    lit.visibilityOf.reset();
    savePicture(renderLit(*device, scene, lit), "soft-mixed-lights");
}

TEST_F(SoftShadowsTest, PcssStaysPutUnderSubTexelCameraMoves)
{
    const scene::Scene scene = contactScene(LightKind::Directional, ShadowFilter::PCSS);
    const render::FrameDesc frame = softFrame(firstLight(LightKind::Directional));
    render::SceneRenderer renderer(*device, scene);
    const auto pictureWithPlansFrom = [&](const scene::Camera& planned) {
        renderer.render(scene.camera, frame, renderer.planShadows(planned, frame));
        return rhi::readTexture(*device, renderer.visibilityImage());
    };
    const rhi::Image still = pictureWithPlansFrom(scene.camera);
    std::vector<scene::Camera> moved;
    for (const glm::vec3 step : {glm::vec3(0.004f, 0.0f, 0.0f), glm::vec3(0.0f, 0.003f, 0.007f),
                                 glm::vec3(-0.011f, 0.0f, 0.002f)}) {
        scene::Camera camera = scene.camera;
        camera.position += step;
        moved.push_back(camera);
    }
    scene::Camera turned = scene.camera;
    turned.forward = glm::normalize(turned.forward + glm::vec3(0.001f, 0.0f, 0.0005f));
    moved.push_back(turned);
    for (std::size_t m = 0; m < moved.size(); ++m) {
        const rhi::Image after = pictureWithPlansFrom(moved[m]);
        std::size_t changed = 0;
        for (std::uint32_t y = 0; y < kSize; ++y)
            for (std::uint32_t x = 0; x < kSize; ++x)
                changed += pixel(still, x, y) != pixel(after, x, y);
        EXPECT_EQ(changed, 0u) << "move " << m << ": " << savePicture(after, fmt::format("soft-moved-{}", m));
    }
}

TEST_F(SoftShadowsTest, CubeMapsAgreeWithAtlasTiles)
{
    const scene::Scene scene = contactScene(LightKind::Point, ShadowFilter::PCSS);
    const LightRef light = firstLight(LightKind::Point);
    const scene::SoftVisibilityMap area = truth(scene, light);
    render::FrameDesc frame = softFrame(light);
    const scene::RenderedVisibility atlas = visibility(scene, frame);
    frame.shadows.other.pointMode = shadows::PointShadowMode::CubeMap;
    frame.shadows.other.cubeMapSize = 1024;
    const scene::RenderedVisibility cube = visibility(scene, frame);
    const scene::SoftTruthFigures atlasError = scene::compareSoftVisibility(area, atlas);
    const scene::SoftTruthFigures cubeError = scene::compareSoftVisibility(area, cube);
    std::printf("point PCSS error: atlas %.4f, cube %.4f\n", atlasError.meanAbsError, cubeError.meanAbsError);
    EXPECT_LT(std::abs(atlasError.meanAbsError - cubeError.meanAbsError), 0.02);
    double difference = 0.0;
    std::size_t compared = 0;
    for (std::size_t i = 0; i < atlas.lit.size(); ++i)
        if (atlas.decided[i] && cube.decided[i]) {
            difference += std::abs(atlas.lit[i] - cube.lit[i]);
            ++compared;
        }
    ASSERT_GT(compared, 0u);
    EXPECT_LT(difference / double(compared), 0.01) << "mean |atlas - cube| over " << compared << " pixels";
}

} // namespace
} // namespace penumbra::testing
