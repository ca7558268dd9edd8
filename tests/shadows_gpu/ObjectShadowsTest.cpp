// Per-object shadow choices (scene::Object::castShadows, receiveShadows) through the caster and lit passes of
// every configuration: a red quad floating over a grey ground under a sun leaning towards +x.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kObjectWidth = 320;
constexpr std::uint32_t kObjectHeight = 180;
constexpr glm::vec3 kObjectSun{0.6f, -1.0f, 0.0f};
constexpr float kQuadHeight = 1.5f;
constexpr glm::vec3 kQuadCentre{0.0f, kQuadHeight, 0.0f};
// The quad's shadow is its footprint moved by kQuadHeight * 0.6 along +x: x in [0.4, 1.4]; this point is in it and
// seen past the quad from the camera.
constexpr glm::vec3 kObjectShadowedGround{1.0f, 0.0f, 0.0f};

enum class Facing { Up, Down }; // towards the sun, or away from it

// Ground (top at y = 0) and "quad", a single-sided 1 x 1 plane with the given facing and shadow choice.
scene::Scene quadOverGround(scene::ShadowCasting casting, Facing facing = Facing::Up)
{
    scene::Scene s;
    const std::uint32_t grey = s.addMaterial({.name = "grey", .baseColor = {0.7f, 0.7f, 0.7f, 1.0f}});
    const std::uint32_t red = s.addMaterial({.name = "red", .baseColor = {0.9f, 0.1f, 0.1f, 1.0f}});
    s.addObject("ground", s.addMesh(scene::makeBox({6.0f, 0.1f, 6.0f})), grey,
                glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}));
    glm::mat4 quad = glm::translate(glm::mat4(1.0f), kQuadCentre);
    if (facing == Facing::Down)
        quad = glm::rotate(quad, glm::radians(180.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    s.objects[s.addObject("quad", s.addMesh(scene::makePlane(0.5f)), red, quad)].castShadows = casting;
    s.lights = {{.name = "sun", .intensity = 2.0f, .direction = glm::normalize(kObjectSun)}};
    s.camera = scene::lookAt({0.0f, 4.0f, 5.0f}, {0.6f, 0.5f, 0.0f}, 0.9f);
    return s;
}

class ObjectShadowsTest : public GpuTest {
protected:
    rhi::Image render(const scene::Scene& scene)
    {
        render::FrameDesc frame;
        frame.width = kObjectWidth;
        frame.height = kObjectHeight;
        rhi::Image image = renderLit(*device, scene, frame);
        const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        pictures_ +=
            savePicture(image, "object-shadows-" + test + "-" + configuration() + "-" + std::to_string(++count_)) + " ";
        return image;
    }

    Rgba at(const rhi::Image& image, const scene::Scene& scene, glm::vec3 world) const
    {
        const glm::uvec2 p = pixelOf(*device, scene.camera, kObjectWidth, kObjectHeight, world);
        return pixel(image, p.x, p.y);
    }

    float shadowLuma(const rhi::Image& image, const scene::Scene& scene) const
    {
        const glm::uvec2 p = pixelOf(*device, scene.camera, kObjectWidth, kObjectHeight, kObjectShadowedGround);
        return luminance(image, p.x, p.y);
    }

    void TearDown() override
    {
        if (HasFailure())
            ADD_FAILURE() << "pictures: " << pictures_;
        GpuTest::TearDown();
    }

private:
    std::string pictures_;
    int count_ = 0;
};

bool isRed(Rgba c) { return c[0] > c[1] + 60 && c[0] > c[2] + 60; }

TEST_F(ObjectShadowsTest, ShadowsOnlyCastsUndrawnAndOffIsDrawnWithoutShadow)
{
    const scene::Scene on = quadOverGround(scene::ShadowCasting::On);
    const scene::Scene off = quadOverGround(scene::ShadowCasting::Off);
    const scene::Scene only = quadOverGround(scene::ShadowCasting::ShadowsOnly);
    const rhi::Image drawn = render(on), unshadowed = render(off), hidden = render(only);
    std::printf("[ objects  ] %s: quad centre on %s, off %s, shadows only %s; shadow luma %.1f, %.1f, %.1f\n",
                configuration().c_str(), describe(at(drawn, on, kQuadCentre)).c_str(),
                describe(at(unshadowed, off, kQuadCentre)).c_str(), describe(at(hidden, only, kQuadCentre)).c_str(),
                shadowLuma(drawn, on), shadowLuma(unshadowed, off), shadowLuma(hidden, only));
    EXPECT_TRUE(isRed(at(drawn, on, kQuadCentre)));
    EXPECT_TRUE(isRed(at(unshadowed, off, kQuadCentre))) << "a quad casting nothing must still be drawn";
    EXPECT_FALSE(isRed(at(hidden, only, kQuadCentre))) << "a shadows-only quad is drawn";
    EXPECT_LT(shadowLuma(drawn, on), 0.5f * shadowLuma(unshadowed, off)) << "the quad's shadow is missing";
    EXPECT_EQ(shadowLuma(hidden, only), shadowLuma(drawn, on)) << "a shadows-only quad casts another shadow";
}

TEST_F(ObjectShadowsTest, TwoSidedCastsFromTheFaceAwayFromTheLight)
{
    // Facing the ground, the sun sees the quad's back face, which a single-sided caster culls.
    const scene::Scene single = quadOverGround(scene::ShadowCasting::On, Facing::Down);
    const scene::Scene both = quadOverGround(scene::ShadowCasting::TwoSided, Facing::Down);
    const float lit = shadowLuma(render(single), single);
    const float shadowed = shadowLuma(render(both), both);
    std::printf("[ objects  ] %s: ground under a quad facing down %.1f, cast two-sided %.1f\n", configuration().c_str(),
                lit, shadowed);
    EXPECT_GT(lit, 150.0f) << "the single-sided quad's back face casts";
    EXPECT_LT(shadowed, 0.5f * lit) << "two-sided casting does not cast the back face";
}

TEST_F(ObjectShadowsTest, ReceiveOffLightsTheObjectAsIfNothingBlockedItsLight)
{
    scene::Scene receiving = quadOverGround(scene::ShadowCasting::On);
    scene::Scene objectOff = receiving;
    objectOff.objects.at(*objectOff.findObject("ground")).receiveShadows = false;
    const scene::Scene unshadowed = quadOverGround(scene::ShadowCasting::Off);
    const float shadowed = shadowLuma(render(receiving), receiving);
    const float notReceiving = shadowLuma(render(objectOff), objectOff);
    const float lit = shadowLuma(render(unshadowed), unshadowed);
    std::printf("[ objects  ] %s: shadow luma %.1f receiving, %.1f not receiving, %.1f without caster\n",
                configuration().c_str(), shadowed, notReceiving, lit);
    EXPECT_LT(shadowed, 0.5f * lit);
    EXPECT_EQ(notReceiving, lit) << "a ground that does not receive shadows is darkened";
}

} // namespace
} // namespace penumbra::testing
