#include "GpuTesting.hpp"
#include "PrecisionScene.hpp"

#include <iostream>

namespace penumbra::testing {
namespace {

using PrecisionTest = GpuTest;

// Two slanted quads 1 unit apart at 10 000 units, near plane 0.1: only reversed-Z with a
// [0, 1] depth range and D32F keeps them apart (conventions note, section 2).
TEST_F(PrecisionTest, ReversedZWithZeroToOneRangeHasNoZFighting)
{
    const ZFighting result = countZFighting(*device);
    std::cout << "[ z-fighting ] " << configuration() << ": " << result.fighting << " of " << result.pixels
              << " pixels\n";
    RecordProperty("zFightingPixels", result.fighting);
    const rhi::Conventions& c = device->conventions();
    if (c.reversedZ() && c.depthRange() == rhi::DepthRange::ZeroToOne)
        EXPECT_EQ(result.fighting, 0);
    else
        EXPECT_GT(result.fighting, 0) << "the standard mapping was expected to lose these surfaces";
}

} // namespace
} // namespace penumbra::testing
