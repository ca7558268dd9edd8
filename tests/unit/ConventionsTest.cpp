#include "penumbra/rhi/Conventions.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

namespace penumbra::rhi {
namespace {

struct ConventionCase {
    DepthRange range;
    bool reversed;
};

class ConventionsTest : public ::testing::TestWithParam<ConventionCase> {
protected:
    Conventions conventions{GetParam().range, GetParam().reversed};

    // Window depth of a view-space point, as the rasterizer computes it for this convention.
    float windowDepth(const glm::mat4& projection, float viewDepth) const
    {
        const glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, -viewDepth, 1.0f);
        const float ndc = clip.z / clip.w;
        return conventions.depthRange() == DepthRange::ZeroToOne ? ndc : 0.5f * ndc + 0.5f;
    }
};

TEST_P(ConventionsTest, PerspectiveMapsNearAndFarToTheirDepths)
{
    const glm::mat4 p = conventions.perspective(1.0f, 1.5f, 0.1f, 100.0f);
    EXPECT_NEAR(windowDepth(p, 0.1f), conventions.nearDepth(), 1e-6f);
    EXPECT_NEAR(windowDepth(p, 100.0f), conventions.farDepth(), 1e-6f);
    EXPECT_EQ(conventions.clearDepth(), conventions.farDepth());
}

TEST_P(ConventionsTest, OrthographicMapsNearAndFarToTheirDepths)
{
    const glm::mat4 p = conventions.orthographic(-2, 2, -1, 1, 0.5f, 20.0f);
    EXPECT_NEAR(windowDepth(p, 0.5f), conventions.nearDepth(), 1e-6f);
    EXPECT_NEAR(windowDepth(p, 20.0f), conventions.farDepth(), 1e-6f);
    const glm::vec4 topLeft = p * glm::vec4(-2, 1, -3, 1);
    EXPECT_FLOAT_EQ(topLeft.x, -1.0f);
    EXPECT_FLOAT_EQ(topLeft.y, 1.0f);
}

TEST_P(ConventionsTest, InfinitePerspectiveApproachesFarDepth)
{
    const glm::mat4 p = conventions.perspectiveInfinite(1.0f, 1.0f, 0.1f);
    EXPECT_NEAR(windowDepth(p, 0.1f), conventions.nearDepth(), 1e-6f);
    EXPECT_NEAR(windowDepth(p, 1e6f), conventions.farDepth(), 1e-6f);
}

TEST_P(ConventionsTest, ViewDepthInvertsTheProjections)
{
    const glm::mat4 perspective = conventions.perspective(1.0f, 1.0f, 0.1f, 100.0f);
    const glm::mat4 orthographic = conventions.orthographic(-1, 1, -1, 1, 0.5f, 20.0f);
    for (float d : {0.5f, 1.0f, 7.0f, 19.0f}) {
        EXPECT_NEAR(conventions.viewDepth(perspective, windowDepth(perspective, d)), d, d * 1e-4f);
        EXPECT_NEAR(conventions.viewDepth(orthographic, windowDepth(orthographic, d)), d, 1e-4f);
    }
}

TEST_P(ConventionsTest, WindowDepthIsWhatTheProjectionGives)
{
    const glm::mat4 perspective = conventions.perspective(1.0f, 1.0f, 0.1f, 100.0f);
    const glm::mat4 orthographic = conventions.orthographic(-1, 1, -1, 1, 0.5f, 20.0f);
    for (float d : {0.1f, 0.5f, 1.0f, 7.0f, 19.0f}) {
        EXPECT_NEAR(conventions.windowDepth(perspective, d), windowDepth(perspective, d), 1e-6f) << d;
        EXPECT_NEAR(conventions.windowDepth(orthographic, d), windowDepth(orthographic, d), 1e-6f) << d;
        EXPECT_NEAR(conventions.viewDepth(perspective, conventions.windowDepth(perspective, d)), d, d * 1e-4f);
    }
}

TEST_P(ConventionsTest, NearerCompareOpOrdersDepthsAsTheProjectionDoes)
{
    const glm::mat4 p = conventions.perspective(1.0f, 1.0f, 0.1f, 100.0f);
    const bool nearerIsLess = windowDepth(p, 2.0f) < windowDepth(p, 3.0f);
    EXPECT_EQ(conventions.depthCompareOp(DepthTest::Nearer), nearerIsLess ? CompareOp::Less : CompareOp::Greater);
    EXPECT_EQ(conventions.shadowCompareOp(), nearerIsLess ? CompareOp::LessOrEqual : CompareOp::GreaterOrEqual);
    EXPECT_EQ(conventions.depthBiasSign(), nearerIsLess ? 1.0f : -1.0f);
}

TEST_P(ConventionsTest, NearClipValueIsTheNdcDepthOfTheNearPlane)
{
    const glm::mat4 p = conventions.perspective(1.0f, 1.0f, 0.1f, 100.0f);
    const glm::vec4 clip = p * glm::vec4(0, 0, -0.1f, 1);
    EXPECT_NEAR(clip.z / clip.w, conventions.nearClipValue(), 1e-6f);
}

TEST_P(ConventionsTest, ClipToTexturePutsNdcTopLeftAtUvOrigin)
{
    const glm::mat4 t = conventions.clipToTexture();
    const glm::vec4 topLeft = t * glm::vec4(-1, 1, conventions.nearClipValue(), 1);
    EXPECT_FLOAT_EQ(topLeft.x, 0.0f);
    EXPECT_FLOAT_EQ(topLeft.y, 0.0f);
    EXPECT_FLOAT_EQ(topLeft.z, conventions.nearDepth());
    const glm::vec4 bottomRight = t * glm::vec4(1, -1, 0, 1);
    EXPECT_FLOAT_EQ(bottomRight.x, 1.0f);
    EXPECT_FLOAT_EQ(bottomRight.y, 1.0f);
}

TEST_P(ConventionsTest, ShaderHeaderStatesTheSameFacts)
{
    const std::string header = conventions.glslHeader();
    const std::string reversed = std::string("#define PENUMBRA_REVERSED_Z ") + (conventions.reversedZ() ? "1" : "0");
    const std::string range = std::string("#define PENUMBRA_DEPTH_ZERO_TO_ONE ") +
                              (conventions.depthRange() == DepthRange::ZeroToOne ? "1" : "0");
    EXPECT_NE(header.find(reversed), std::string::npos) << header;
    EXPECT_NE(header.find(range), std::string::npos) << header;
}

INSTANTIATE_TEST_SUITE_P(, ConventionsTest,
                         ::testing::Values(ConventionCase{DepthRange::ZeroToOne, false},
                                           ConventionCase{DepthRange::ZeroToOne, true},
                                           ConventionCase{DepthRange::MinusOneToOne, false},
                                           ConventionCase{DepthRange::MinusOneToOne, true}),
                         [](const ::testing::TestParamInfo<ConventionCase>& param) {
                             return std::string(param.param.range == DepthRange::ZeroToOne ? "ZeroToOne"
                                                                                           : "MinusOneToOne") +
                                    (param.param.reversed ? "Reversed" : "");
                         });

} // namespace
} // namespace penumbra::rhi
