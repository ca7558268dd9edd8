// Contact shadows (shadows.contact) against the CPU ray cast, in every configuration: the contact scene seen low from
// its shadowed side at 160 x 90 with one cascade in a 512-texel atlas, whose map leaves lit gaps at the pole's foot and
// under the fence slats. The gaps are truth::contactGapPixels (decided by the map, shadowed by a caster within
// contact.length in the ray cast, rendered lit; the comparison's own figures leave out pixels within a filter's reach
// of a shadow edge, which is where those gaps are): contact shadows must close some of them without darkening a
// pixel that truly sees the light (the comparison's acne does not rise). The negative controls march with a thickness
// of 10 metres, which ignores it (surfaces then hide everything behind them, and the halos it draws are caught), and
// a march too short to reach a caster, whose gaps must stay. The same for a spot and a point light over the pole and
// the fence (the sun taken away; small tiles of a 512-texel local atlas, whose texels and biases leave the gaps),
// which the march goes towards by their position.
#include "GpuTesting.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/truth/GroundTruth.hpp"
#include "penumbra/truth/ShadowTruth.hpp"
#include "penumbra/truth/TruthComparison.hpp"

#include <cstddef>
#include <cstdio>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <memory>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kContactWidth = 160;
constexpr std::uint32_t kContactHeight = 90;
constexpr scene::LightRef kSun{scene::LightKind::Directional, 0};
constexpr scene::LightRef kContactSpot{scene::LightKind::Spot, 0};
constexpr scene::LightRef kContactPoint{scene::LightKind::Point, 0};
// Casters within the default march's length count: what contact shadows can close.
constexpr float kReach = shadows::ContactShadowSettings{}.length;

render::FrameDesc contactFrame(bool contact, float thickness = shadows::ContactShadowSettings{}.thickness,
                               float length = kReach)
{
    render::FrameDesc frame;
    frame.width = kContactWidth;
    frame.height = kContactHeight;
    frame.shadows.directional.atlasSize = 512;
    // One cascade over the 100 m shadow distance: texels of 0.4 m, whose biases lift the shadows off their casters.
    frame.shadows.directional.cascadeCount = 1;
    frame.shadows.contact.shadows = contact ? shadows::Toggle::On : shadows::Toggle::Off;
    frame.shadows.contact.thickness = thickness;
    frame.shadows.contact.length = length;
    frame.visibilityOf = kSun;
    return frame;
}

// contactFrame at 320 x 180, where the slats seen past the fence (ContactShadowsTest::lookPastTheFence) cover a few
// pixels each.
render::FrameDesc pastTheFenceFrame(bool contact, float thickness = shadows::ContactShadowSettings{}.thickness)
{
    render::FrameDesc frame = contactFrame(contact, thickness);
    frame.width = 2 * kContactWidth;
    frame.height = 2 * kContactHeight;
    return frame;
}

// contactFrame for the spot and point lights (contactLocalLights: both, the nearest first), seen through `light`'s
// visibility view: tiles of at most 64 texels in a 512-texel local atlas, which leave gaps at the pole's foot and under
// the slats.
render::FrameDesc localContactFrame(bool contact, scene::LightRef light, float length = kReach)
{
    render::FrameDesc frame = contactFrame(contact, shadows::ContactShadowSettings{}.thickness, length);
    frame.shadows.local.atlasSize = 512;
    frame.shadows.local.tileResolution = 64;
    frame.shadows.local.minTileResolution = 16;
    frame.shadows.contact.localLights = 2;
    frame.visibilityOf = light;
    return frame;
}

class ContactShadowsTest : public GpuTest {
public:
    void SetUp() override
    {
        GpuTest::SetUp();
        scene_ = scenes::makeContactScene();
        // Low over the shadowed side, the pole's foot and the fence in view: ground behind the slats and the pole
        // that a march ignoring the thickness would shadow.
        scene_.camera = scene::lookAt({4.0f, 2.0f, -1.0f}, {0.0f, 0.0f, 1.0f}, glm::radians(55.0f), {0.0f, 1.0f, 0.0f});
    }

    void TearDown() override
    {
        renderer_.reset();
        GpuTest::TearDown();
    }

    struct Figures {
        std::size_t gaps = 0; // truly shadowed within contact.length of the caster, rendered lit
        std::size_t acne = 0; // the comparison's: truly lit, rendered dark, away from edges
    };

    // The contact scene's spot and point lights instead of its sun (scenes::makeContactLocalLightsScene), from the
    // same camera.
    void useLocalLights() { scene_ = scenes::makeContactLocalLightsScene(); }

    // The pole, the slab and the slats drawn through the alpha test, with nothing cut away (alpha 1).
    void alphaTestCasters()
    {
        for (scene::Material& material : scene_.materials)
            if (material.name == "caster")
                material.caster = scene::CasterMode::Clip;
    }

    // From the lit side of the fence, looking down past the slats at the ground beyond them: a march from that ground
    // towards the sun passes behind the 6 cm slats in view without meeting them.
    void lookPastTheFence()
    {
        scene_.camera = scene::lookAt({-0.2f, 2.0f, 3.6f}, {0.3f, 0.0f, 2.2f}, glm::radians(55.0f), {0.0f, 1.0f, 0.0f});
    }

    // The visibility view of `frame`'s light (FrameDesc::visibilityOf) against the ray cast.
    Figures measure(const render::FrameDesc& frame, const char* name)
    {
        render::SceneRenderer& renderer = sceneRenderer();
        const render::ShadowPlans plans = renderer.planShadows(scene_.camera, frame);
        renderer.render(scene_.camera, frame, plans);
        const truth::RenderedVisibility rendered =
            truth::renderedVisibility(rhi::readTexture(*device, renderer.visibilityImage()));
        if (!shadowRays_) {
            const truth::RayCaster cameraRays(scene_, truth::RayKind::Camera);
            gbuffer_ = truth::traceGBuffer(scene_, cameraRays, scene_.camera, frame.width, frame.height);
            shadowRays_ = std::make_unique<truth::RayCaster>(scene_);
        }
        const truth::RayCaster& shadowRays = *shadowRays_;
        const truth::CpuGBuffer& gbuffer = gbuffer_;
        const truth::LightTruthTrace trace =
            truth::traceLightTruth(scene_, shadowRays, gbuffer, plans, frame.shadows, *frame.visibilityOf);
        const truth::TruthComparison c = truth::compareLightTruth(trace, shadowRays, gbuffer, rendered);
        const truth::ContactGapFigures gaps =
            truth::contactGapPixels(gbuffer, trace.visibility, rendered, shadowRays, trace.rays, kReach);
        const Figures f{.gaps = gaps.gaps, .acne = c.acne()};
        std::printf("[ contact  ] %s %s %s: %zu gap pixels of %zu, acne %zu (lit %zu, shadowed %zu compared)\n",
                    configuration().c_str(), scene::lightKindName(frame.visibilityOf->kind), name, f.gaps,
                    gaps.shadowed, f.acne, c.lit.compared, c.shadowed.compared);
        return f;
    }

    rhi::Image visibility(const render::FrameDesc& frame)
    {
        render::SceneRenderer& renderer = sceneRenderer();
        renderer.render(scene_.camera, frame);
        return rhi::readTexture(*device, renderer.visibilityImage());
    }

private:
    // One renderer for every frame of a test, made at its first frame (after useLocalLights): its pipelines are
    // compiled once.
    render::SceneRenderer& sceneRenderer()
    {
        if (!renderer_)
            renderer_ = std::make_unique<render::SceneRenderer>(*device, scene_);
        return *renderer_;
    }

    scene::Scene scene_;
    std::unique_ptr<render::SceneRenderer> renderer_;
    // The camera's pixels and the shadow rays' BVH, traced at a test's first measure.
    truth::CpuGBuffer gbuffer_;
    std::unique_ptr<truth::RayCaster> shadowRays_;
};

TEST_F(ContactShadowsTest, CloseGapsWithoutAcne)
{
    const Figures off = measure(contactFrame(false), "off");
    const Figures on = measure(contactFrame(true), "on");
    ASSERT_GT(off.gaps, 0u) << "the map alone must leave gaps for contact shadows to close";
    EXPECT_LT(on.gaps, off.gaps);
    EXPECT_LE(on.acne, off.acne);
}

// The screen-space path and 4x MSAA (whose single-sampled contact prepass the march reads) give the forward path's
// contact shadows, pixel for pixel, in the visibility view.
TEST_F(ContactShadowsTest, EveryPathMarchesTheSameDepth)
{
    const render::FrameDesc forward = contactFrame(true);
    render::FrameDesc screenSpace = forward;
    screenSpace.shadowPath = render::ShadowPath::ScreenSpace;
    render::FrameDesc msaa = forward;
    msaa.msaa = 4;
    const rhi::Image reference = visibility(forward);
    EXPECT_EQ(visibility(screenSpace).bytes, reference.bytes) << "screen-space path";
    EXPECT_EQ(visibility(msaa).bytes, reference.bytes) << "4x MSAA";
}

TEST_F(ContactShadowsTest, ThicknessIgnoredCatchesFault)
{
    const Figures off = measure(contactFrame(false), "off");
    const Figures ignored = measure(contactFrame(true, 10.0f), "thickness 10 m");
    EXPECT_GT(ignored.acne, off.acne) << "a march that ignores the thickness must darken truly lit pixels";
}

// Ground seen past thin casters: the march's ray passes behind the slats in view, within a thickness band deeper than
// they are, and must not count them.
TEST_F(ContactShadowsTest, ThinCastersInFrontDarkenNothing)
{
    lookPastTheFence();
    const Figures off = measure(pastTheFenceFrame(false), "off, past the fence");
    EXPECT_LE(measure(pastTheFenceFrame(true), "on, past the fence").acne, off.acne);
}

// The former default thickness, 0.2 m, more than three times the slats' depth: its halos beyond them are caught.
TEST_F(ContactShadowsTest, ThickerThanTheCastersCatchesFault)
{
    lookPastTheFence();
    const Figures off = measure(pastTheFenceFrame(false), "off, past the fence");
    EXPECT_GT(measure(pastTheFenceFrame(true, 0.2f), "thickness 0.2 m, past the fence").acne, off.acne)
        << "a thickness beyond the slats' must darken the ground seen past them";
}

// The same slats alpha-tested (no holes): cards to the march, which count only where its ray crosses one between two
// samples (view_depth.glsl), so even the 0.2 m band leaves the ground seen past them lit.
TEST_F(ContactShadowsTest, AlphaTestedCastersAreCards)
{
    lookPastTheFence();
    alphaTestCasters();
    const Figures off = measure(pastTheFenceFrame(false), "off, past alpha-tested slats");
    EXPECT_LE(measure(pastTheFenceFrame(true, 0.2f), "thickness 0.2 m, past alpha-tested slats").acne, off.acne);
}

// A march of 2 cm reaches no caster: the gap count (truth::contactGapPixels, casters within the default length)
// must not fall, or it would credit contact shadows with what they did not do.
TEST_F(ContactShadowsTest, MarchTooShortCatchesFault)
{
    const Figures off = measure(contactFrame(false), "off");
    const Figures tooShort = measure(contactFrame(true, shadows::ContactShadowSettings{}.thickness, 0.02f), "2 cm");
    EXPECT_EQ(tooShort.gaps, off.gaps) << "a march that reaches no caster closes no gap";
}

// A spot and a point light: contact shadows towards their position close some of the gaps their small tiles leave,
// and darken no pixel that truly sees the light.
TEST_F(ContactShadowsTest, LocalLightsCloseGapsWithoutAcne)
{
    useLocalLights();
    for (const scene::LightRef light : {kContactSpot, kContactPoint}) {
        const Figures off = measure(localContactFrame(false, light), "off");
        const Figures on = measure(localContactFrame(true, light), "on");
        ASSERT_GT(off.gaps, 0u) << scene::lightKindName(light.kind) << ": the map alone must leave gaps";
        EXPECT_LT(on.gaps, off.gaps) << scene::lightKindName(light.kind);
        EXPECT_LE(on.acne, off.acne) << scene::lightKindName(light.kind);
    }
}

// The local lights' contact shadows, forward, on the screen-space path and with 4x MSAA: the same pixels.
TEST_F(ContactShadowsTest, LocalLightsEveryPathMarchesTheSameDepth)
{
    useLocalLights();
    for (const scene::LightRef light : {kContactSpot, kContactPoint}) {
        const render::FrameDesc forward = localContactFrame(true, light);
        render::FrameDesc screenSpace = forward;
        screenSpace.shadowPath = render::ShadowPath::ScreenSpace;
        render::FrameDesc msaa = forward;
        msaa.msaa = 4;
        const rhi::Image reference = visibility(forward);
        EXPECT_EQ(visibility(screenSpace).bytes, reference.bytes)
            << scene::lightKindName(light.kind) << ", screen-space";
        EXPECT_EQ(visibility(msaa).bytes, reference.bytes) << scene::lightKindName(light.kind) << ", 4x MSAA";
    }
}

// A march of 2 cm towards the spot or point light reaches no caster: their gaps must stay.
TEST_F(ContactShadowsTest, LocalLightsMarchTooShortCatchesFault)
{
    useLocalLights();
    for (const scene::LightRef light : {kContactSpot, kContactPoint}) {
        const Figures off = measure(localContactFrame(false, light), "off");
        const Figures tooShort = measure(localContactFrame(true, light, 0.02f), "2 cm");
        EXPECT_EQ(tooShort.gaps, off.gaps) << scene::lightKindName(light.kind);
    }
}

} // namespace
} // namespace penumbra::testing
