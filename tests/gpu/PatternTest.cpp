#include "GpuTesting.hpp"
#include "TestPattern.hpp"

namespace penumbra::testing {
namespace {

using PatternTest = GpuTest;

// The markers are drawn in canonical NDC (y up): red at the top-left, green at the
// top-right, blue at the bottom-left. Row 0 of the readback is the top of the picture.
TEST_F(PatternTest, MarkersLandWhereCanonicalNdcPutsThem)
{
    pattern::PatternRenderer renderer(*device, {.width = 64, .height = 64});
    renderer.render(pattern::testPattern());
    const rhi::Image image = renderer.color();
    const std::string picture = savePicture(image, configuration() + "/pattern");

    const Rgba red{255, 0, 0, 255}, green{0, 255, 0, 255}, blue{0, 0, 255, 255}, black{0, 0, 0, 255};
    EXPECT_EQ(pixel(image, 4, 4), red) << describe(pixel(image, 4, 4)) << " in " << picture;
    EXPECT_EQ(pixel(image, 59, 4), green) << describe(pixel(image, 59, 4)) << " in " << picture;
    EXPECT_EQ(pixel(image, 4, 59), blue) << describe(pixel(image, 4, 59)) << " in " << picture;
    EXPECT_EQ(pixel(image, 59, 59), black) << describe(pixel(image, 59, 59)) << " in " << picture;
}

} // namespace
} // namespace penumbra::testing
