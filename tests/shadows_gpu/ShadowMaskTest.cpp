// The GPU shadow masks of the key light, a spot light and point lights against a CPU ray cast of the same
// pixels (scene::GroundTruth).
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/GroundTruth.hpp"
#include "penumbra/scene/TestScenes.hpp"

#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kWidth = 960;
constexpr std::uint32_t kHeight = 540;
// Pixels this close to a change of ground-truth class or object are shadow or silhouette edges.
constexpr int kEdgeMargin = 2;
// Direct light below this (8-bit sRGB luminance) is too grazing to tell shadow from light.
constexpr float kMinimumDirect = 24.0f;

// Without ambient light a single-light scene is black where the light is blocked, so a pixel is shadowed
// when it keeps less than half the brightness it has with shadows off.
struct ShadowMask {
    rhi::Image shadowed;
    rhi::Image unshadowed;

    bool decided(std::uint32_t x, std::uint32_t y) const { return luminance(unshadowed, x, y) >= kMinimumDirect; }
    bool inShadow(std::uint32_t x, std::uint32_t y) const
    {
        return luminance(shadowed, x, y) < 0.5f * luminance(unshadowed, x, y);
    }
};

class ShadowMaskTest : public GpuTest {
public:
    ShadowMask renderMask(const scene::Scene& scene, float& cascade1TexelSize,
                          const shadows::ShadowSettings& settings = {})
    {
        render::FrameDesc frame;
        frame.shadows = settings;
        frame.width = kWidth;
        frame.height = kHeight;
        frame.ambient = glm::vec3(0.0f);
        render::SceneRenderer renderer(*device, scene);
        renderer.render(scene.camera, frame);
        ShadowMask mask;
        mask.shadowed = rhi::readTexture(*device, renderer.litImage());
        if (!renderer.plan().lights.empty())
            cascade1TexelSize = renderer.plan().lights.at(0).cascades.at(1).fit.texelSize;
        mask.unshadowed = renderLit(*device, withoutShadows(scene), frame);
        return mask;
    }
};

bool nearEdge(const scene::CpuGBuffer& gbuffer, const scene::LightVisibilityMask& truth, std::uint32_t x,
              std::uint32_t y)
{
    for (int dy = -kEdgeMargin; dy <= kEdgeMargin; ++dy)
        for (int dx = -kEdgeMargin; dx <= kEdgeMargin; ++dx) {
            const int nx = int(x) + dx, ny = int(y) + dy;
            if (nx < 0 || ny < 0 || nx >= int(truth.width) || ny >= int(truth.height))
                return true;
            if (truth.at(nx, ny) != truth.at(x, y) || gbuffer.at(nx, ny).object != gbuffer.at(x, y).object)
                return true;
        }
    return false;
}

bool nearLitPixel(const scene::LightVisibilityMask& truth, std::uint32_t x, std::uint32_t y)
{
    for (int dy = -kEdgeMargin; dy <= kEdgeMargin; ++dy)
        for (int dx = -kEdgeMargin; dx <= kEdgeMargin; ++dx) {
            const int nx = int(x) + dx, ny = int(y) + dy;
            if (nx >= 0 && ny >= 0 && nx < int(truth.width) && ny < int(truth.height) &&
                truth.at(nx, ny) == scene::LightVisibility::Lit)
                return true;
        }
    return false;
}

// Distance in the ground plane from p to the footprint [min, max] of a box standing on it.
float footprintDistance(glm::vec3 p, glm::vec2 min, glm::vec2 max)
{
    const glm::vec2 q{p.x, p.z};
    return glm::length(glm::max(glm::max(min - q, q - max), glm::vec2(0.0f)));
}

struct Agreement {
    std::size_t compared = 0;
    std::size_t agreeing = 0;
    std::size_t litCompared = 0;
    std::size_t acne = 0;
};

// Pixels away from shadow and silhouette edges where the light reaches enough to decide.
Agreement compareWithTruth(const ShadowMask& mask, const scene::CpuGBuffer& gbuffer,
                           const scene::LightVisibilityMask& truth)
{
    Agreement a;
    for (std::uint32_t y = 0; y < kHeight; ++y)
        for (std::uint32_t x = 0; x < kWidth; ++x) {
            const scene::LightVisibility expected = truth.at(x, y);
            if ((expected != scene::LightVisibility::Lit && expected != scene::LightVisibility::Shadowed) ||
                !mask.decided(x, y) || nearEdge(gbuffer, truth, x, y))
                continue;
            const bool shadowed = mask.inShadow(x, y);
            ++a.compared;
            a.agreeing += shadowed == (expected == scene::LightVisibility::Shadowed);
            if (expected == scene::LightVisibility::Lit) {
                ++a.litCompared;
                a.acne += shadowed;
            }
        }
    return a;
}

// The mixed scene with one spot or point light kept, brightened to decide most of what it reaches; the
// dithered caster made solid, as the ray cast counts it (its shadow is a stipple of about 60%).
scene::Scene oneLocalLight(bool spot, std::size_t index)
{
    scene::Scene scene = scene::makeMixedLightsScene();
    scene.lights.clear();
    if (spot) {
        scene.spotLights = {scene.spotLights[index]};
        scene.spotLights[0].intensity *= 4.0f;
        scene.pointLights.clear();
    } else {
        scene.pointLights = {scene.pointLights[index]};
        scene.pointLights[0].intensity *= 6.0f;
        scene.spotLights.clear();
    }
    for (scene::Material& material : scene.materials)
        if (material.caster == scene::CasterMode::Dither)
            material.caster = scene::CasterMode::On;
    return scene;
}

// One spot or point light alone (no ambient, no other light) against the ray cast towards its position.
void checkPositionalLight(ShadowMaskTest& test, const scene::Scene& scene, const std::string& name,
                          glm::vec3 position, const ShadowMask& mask)
{
    const scene::RayCaster cameraRays(scene, scene::RayKind::Camera);
    const scene::RayCaster shadowRays(scene);
    const scene::CpuGBuffer gbuffer = scene::traceGBuffer(scene, cameraRays, scene.camera, kWidth, kHeight);
    const scene::LightVisibilityMask truth = scene::tracePositionalLightVisibility(scene, shadowRays, gbuffer, position);
    const Agreement a = compareWithTruth(mask, gbuffer, truth);
    const double agreement = double(a.agreeing) / double(a.compared);
    std::printf("[ truth    ] %s %s: %zu of %zu pixels agree (%.3f%%); acne %zu of %zu lit\n", configuration().c_str(),
                name.c_str(), a.agreeing, a.compared, 100.0 * agreement, a.acne, a.litCompared);
    test.RecordProperty(name + ".agreement", std::to_string(agreement));
    EXPECT_GT(a.compared, std::size_t(kWidth) * kHeight / 50) << name << ": the light must reach a good part of the picture";
    EXPECT_GE(agreement, 0.99) << name;
    EXPECT_LE(a.acne, a.litCompared / 1000) << name << ": lit surfaces shadowed away from shadow edges";
    if (::testing::Test::HasFailure())
        ADD_FAILURE() << "pictures: " << savePicture(mask.shadowed, "truth-" + configuration() + "-" + name + "-shadowed")
                      << ", " << savePicture(mask.unshadowed, "truth-" + configuration() + "-" + name + "-unshadowed");
}

TEST_F(ShadowMaskTest, SpotShadowAgreesWithTheRayCast)
{
    scene::Scene scene = oneLocalLight(true, 2);
    scene.spotLights[0].outerAngle = 0.9f; // a wide cone over several objects
    float texel = 0.0f;
    checkPositionalLight(*this, scene, "spot", scene.spotLights[0].position, renderMask(scene, texel));
}

TEST_F(ShadowMaskTest, PointShadowsAgreeWithTheRayCast)
{
    const scene::Scene mixed = oneLocalLight(false, 1);
    float texel = 0.0f;
    checkPositionalLight(*this, mixed, "point", mixed.pointLights[0].position, renderMask(mixed, texel));

    scene::Scene room = scene::makePointLightRoomScene();
    room.pointLights.pop_back();
    checkPositionalLight(*this, room, "room", room.pointLights[0].position, renderMask(room, texel));
    shadows::ShadowSettings cubeMaps;
    cubeMaps.other.pointMode = shadows::PointShadowMode::CubeMap;
    checkPositionalLight(*this, room, "room-cube-map", room.pointLights[0].position, renderMask(room, texel, cubeMaps));
}

TEST_F(ShadowMaskTest, ShadowMapAgreesWithTheRayCastAndHasNoAcneOrPeterPanning)
{
    const scene::Scene scene = scene::makeSingleLightScene();
    float texel = 0.0f;
    const ShadowMask mask = renderMask(scene, texel);
    const scene::RayCaster cameraRays(scene, scene::RayKind::Camera);
    const scene::RayCaster shadowRays(scene);
    const scene::CpuGBuffer gbuffer = scene::traceGBuffer(scene, cameraRays, scene.camera, kWidth, kHeight);
    const scene::LightVisibilityMask truth = scene::traceLightVisibility(scene, shadowRays, gbuffer, scene.lights[0]);

    const std::uint32_t ground = *scene.findObject("ground");
    const scene::Object& cube = scene.objects[*scene.findObject("standing cube")];
    const glm::vec2 footprintMin{cube.worldBounds.min.x, cube.worldBounds.min.z};
    const glm::vec2 footprintMax{cube.worldBounds.max.x, cube.worldBounds.max.z};

    std::size_t compared = 0, agreeing = 0, litCompared = 0, acne = 0, contactSamples = 0, contactGaps = 0;
    for (std::uint32_t y = 0; y < kHeight; ++y)
        for (std::uint32_t x = 0; x < kWidth; ++x) {
            const scene::LightVisibility expected = truth.at(x, y);
            if (expected != scene::LightVisibility::Lit && expected != scene::LightVisibility::Shadowed)
                continue;
            if (!mask.decided(x, y))
                continue;
            const bool shadowed = mask.inShadow(x, y);
            // Peter-panning: ground in the cube's shadow more than one shadow texel from its footprint must
            // be dark on the GPU too, right up to the cube (the lateral shadow edges are left out).
            const scene::GBufferSample& sample = gbuffer.at(x, y);
            if (sample.object == ground && expected == scene::LightVisibility::Shadowed && !nearLitPixel(truth, x, y)) {
                const float d = footprintDistance(sample.position, footprintMin, footprintMax);
                if (d > texel && d < 4.0f * texel) {
                    ++contactSamples;
                    contactGaps += !shadowed;
                }
            }
            if (nearEdge(gbuffer, truth, x, y))
                continue;
            ++compared;
            agreeing += shadowed == (expected == scene::LightVisibility::Shadowed);
            if (expected == scene::LightVisibility::Lit) {
                ++litCompared;
                acne += shadowed;
            }
        }
    const double agreement = double(agreeing) / double(compared);
    std::printf("[ truth    ] %s: %zu of %zu pixels agree (%.3f%%); acne %zu of %zu lit; contact gaps %zu of %zu "
                "(texel %.4f)\n",
                configuration().c_str(), agreeing, compared, 100.0 * agreement, acne, litCompared, contactGaps,
                contactSamples, texel);
    RecordProperty("agreement", std::to_string(agreement));
    ASSERT_GT(compared, std::size_t(kWidth) * kHeight / 4) << "the comparison must cover most of the picture";
    EXPECT_GE(agreement, 0.99);
    EXPECT_LE(acne, litCompared / 1000) << "lit surfaces shadowed away from shadow edges";
    ASSERT_GT(contactSamples, 20u) << "the cube's contact shadow must be in view";
    EXPECT_EQ(contactGaps, 0u) << "a gap between the cube and its shadow wider than one texel";
    if (HasFailure()) {
        ADD_FAILURE() << "pictures: " << savePicture(mask.shadowed, "truth-" + configuration() + "-shadowed") << ", "
                      << savePicture(mask.unshadowed, "truth-" + configuration() + "-unshadowed");
    }
}

} // namespace
} // namespace penumbra::testing
