// Contact shadows (shadows.contact) against the CPU ray cast, in every configuration: the contact scene seen low from
// its shadowed side at 160 x 90 with one cascade in a 512-texel atlas, whose map leaves lit gaps at the pole's foot and
// under the fence slats. The gaps are truth::contactGapPixels (decided by the map, shadowed by a caster within
// contact.length in the ray cast, rendered lit; the comparison's own figures leave out pixels within a filter's reach
// of a shadow edge, which is where those gaps are): contact shadows must close some of them without darkening a
// pixel that truly sees the light (the comparison's acne does not rise). The negative controls march with a thickness
// of 10 metres, which ignores it (surfaces then hide everything behind them, and the halos it draws are caught), and
// a march too short to reach a caster, whose gaps must stay.
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

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kContactWidth = 160;
constexpr std::uint32_t kContactHeight = 90;
constexpr scene::LightRef kSun{scene::LightKind::Directional, 0};
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

    struct Figures {
        std::size_t gaps = 0; // truly shadowed within contact.length of the caster, rendered lit
        std::size_t acne = 0; // the comparison's: truly lit, rendered dark, away from edges
    };

    // The sun's visibility view with `frame` against the ray cast.
    Figures measure(const render::FrameDesc& frame, const char* name)
    {
        render::SceneRenderer renderer(*device, scene_);
        const render::ShadowPlans plans = renderer.planShadows(scene_.camera, frame);
        renderer.render(scene_.camera, frame, plans);
        const truth::RenderedVisibility rendered =
            truth::renderedVisibility(rhi::readTexture(*device, renderer.visibilityImage()));
        const truth::RayCaster cameraRays(scene_, truth::RayKind::Camera);
        const truth::RayCaster shadowRays(scene_);
        const truth::CpuGBuffer gbuffer =
            truth::traceGBuffer(scene_, cameraRays, scene_.camera, kContactWidth, kContactHeight);
        const truth::LightTruthTrace trace =
            truth::traceLightTruth(scene_, shadowRays, gbuffer, plans, frame.shadows, kSun);
        const truth::TruthComparison c = truth::compareLightTruth(trace, shadowRays, gbuffer, rendered);
        const truth::ContactGapFigures gaps =
            truth::contactGapPixels(gbuffer, trace.visibility, rendered, shadowRays, trace.rays, kReach);
        const Figures f{.gaps = gaps.gaps, .acne = c.acne()};
        std::printf("[ contact  ] %s %s: %zu gap pixels of %zu, acne %zu (lit %zu, shadowed %zu compared)\n",
                    configuration().c_str(), name, f.gaps, gaps.shadowed, f.acne, c.lit.compared, c.shadowed.compared);
        return f;
    }

    rhi::Image visibility(const render::FrameDesc& frame)
    {
        render::SceneRenderer renderer(*device, scene_);
        renderer.render(scene_.camera, frame);
        return rhi::readTexture(*device, renderer.visibilityImage());
    }

private:
    scene::Scene scene_;
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

// A march of 2 cm reaches no caster: the gap count (truth::contactGapPixels, casters within the default length)
// must not fall, or it would credit contact shadows with what they did not do.
TEST_F(ContactShadowsTest, MarchTooShortCatchesFault)
{
    const Figures off = measure(contactFrame(false), "off");
    const Figures tooShort = measure(contactFrame(true, shadows::ContactShadowSettings{}.thickness, 0.02f), "2 cm");
    EXPECT_EQ(tooShort.gaps, off.gaps) << "a march that reaches no caster closes no gap";
}

} // namespace
} // namespace penumbra::testing
