// The custom pass renders the same on every configuration: a parity test with penumbra::parity's
// GoogleTest helper. On failure the report (index.html, parity.json, heat maps) is written into
// test-output/parity/CustomPass/SameOnEveryConfiguration/ (or under $PENUMBRA_TEST_OUTPUT).
#include "CustomPass.hpp"

#include <penumbra/parity/GoogleTest.hpp>

#include <gtest/gtest.h>

using namespace penumbra;

std::vector<parity::Picture> renderCustomPass(rhi::Device& device, const rhi::NamedConfiguration&)
{
    examples::CustomPass pass(device, 128, 128);
    pass.render();
    return {parity::colorPicture("colour", pass.color()),
            parity::viewDepthPicture("depth", pass.depth(), pass.projection())};
}

TEST(CustomPass, SameOnEveryConfiguration)
{
    parity::Options options;
    // The colours byte-identical; view depth (3 to 5 units) within 1e-4 of a unit, the raw depth
    // bit-identical where two configurations share depth range and reversal (the default).
    options.thresholds["depth"] = {.maxDifference = 1e-4};
    PENUMBRA_EXPECT_PARITY(renderCustomPass, options);
}
