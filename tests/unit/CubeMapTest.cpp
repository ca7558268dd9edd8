#include "penumbra/rhi/CubeMap.hpp"

#include <cmath>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

namespace penumbra::rhi {
namespace {

// The face and (s, t) that hardware cube sampling gives direction d: GL 4.5 table 8.19, Vulkan
// "Cube Map Face Selection", written out here independently of CubeMap.cpp.
struct Lookup {
    CubeFace face;
    glm::vec2 st;
};

Lookup sampleCube(const glm::vec3& d)
{
    const glm::vec3 a = glm::abs(d);
    float sc = 0.0f, tc = 0.0f, ma = 0.0f;
    CubeFace face{};
    if (a.x >= a.y && a.x >= a.z) {
        face = d.x > 0 ? CubeFace::PositiveX : CubeFace::NegativeX;
        sc = d.x > 0 ? -d.z : d.z;
        tc = -d.y;
        ma = a.x;
    } else if (a.y >= a.z) {
        face = d.y > 0 ? CubeFace::PositiveY : CubeFace::NegativeY;
        sc = d.x;
        tc = d.y > 0 ? d.z : -d.z;
        ma = a.y;
    } else {
        face = d.z > 0 ? CubeFace::PositiveZ : CubeFace::NegativeZ;
        sc = d.z > 0 ? d.x : -d.x;
        tc = -d.y;
        ma = a.z;
    }
    return {face, {0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)}};
}

const Conventions conventionsToTest[] = {{DepthRange::ZeroToOne, false},
                                         {DepthRange::ZeroToOne, true},
                                         {DepthRange::MinusOneToOne, false},
                                         {DepthRange::MinusOneToOne, true}};

TEST(CubeMapTest, FaceViewsPutEveryPointWhereCubeSamplingLooksForIt)
{
    const glm::vec3 light(3.0f, -2.0f, 0.5f);
    for (const Conventions& conventions : conventionsToTest) {
        const glm::mat4 projection = cubeFaceProjection(conventions, 0.1f, 50.0f);
        for (float x : {-0.9f, -0.3f, 0.2f, 0.8f})
            for (float y : {-0.7f, -0.1f, 0.4f, 0.95f})
                for (float z : {-1.1f, -0.5f, 0.6f, 1.2f}) {
                    const glm::vec3 d(x, y, z);
                    const Lookup expected = sampleCube(d);
                    const glm::vec4 clip = projection * cubeFaceView(expected.face, light) * glm::vec4(light + d, 1.0f);
                    ASSERT_GT(clip.w, 0.0f);
                    const glm::vec4 uv = conventions.clipToTexture() * (clip / clip.w);
                    EXPECT_NEAR(uv.x, expected.st.x, 1e-5f) << x << ' ' << y << ' ' << z;
                    EXPECT_NEAR(uv.y, expected.st.y, 1e-5f) << x << ' ' << y << ' ' << z;
                    EXPECT_NEAR(clip.w, cubeFaceViewDepth(d), 1e-5f);
                    // clipToTexture's z is the window depth.
                    EXPECT_NEAR(conventions.windowDepth(projection, cubeFaceViewDepth(d)), uv.z, 1e-6f);
                }
    }
}

TEST(CubeMapTest, FaceProjectionReachesTheFaceEdgesExactly)
{
    // Exact edges make neighbouring faces meet without a gap or overlap of texels.
    const glm::mat4 p = cubeFaceProjection(Conventions(DepthRange::ZeroToOne, false), 0.1f, 10.0f);
    EXPECT_EQ(p[0][0], 1.0f);
    EXPECT_EQ(p[1][1], 1.0f);
}

TEST(CubeMapTest, FaceViewsAreMirroredSoCullingSwaps)
{
    for (CubeFace face : allCubeFaces) {
        const glm::mat4 view = cubeFaceView(face, glm::vec3(1.0f, 2.0f, 3.0f));
        EXPECT_FLOAT_EQ(glm::determinant(view), -1.0f);
        EXPECT_TRUE(flipsWinding(view));
        EXPECT_EQ(viewCullMode(view, CullMode::Back), CullMode::Front);
        EXPECT_EQ(viewCullMode(view, CullMode::None), CullMode::None);
    }
    EXPECT_EQ(cubeFaceCullMode(CullMode::Back), CullMode::Front);
    EXPECT_EQ(cubeFaceCullMode(CullMode::Front), CullMode::Back);
    EXPECT_FALSE(flipsWinding(glm::mat4(1.0f)));
    EXPECT_EQ(viewCullMode(glm::mat4(1.0f), CullMode::Back), CullMode::Back);
}

TEST(CubeMapTest, LayersAreSixPerCubeInFaceOrder)
{
    EXPECT_EQ(cubeLayer(0, CubeFace::PositiveX), 0u);
    EXPECT_EQ(cubeLayer(0, CubeFace::NegativeZ), 5u);
    EXPECT_EQ(cubeLayer(1, CubeFace::NegativeX), 7u);
    EXPECT_EQ(cubeLayer(2, CubeFace::PositiveY), 14u);
}

} // namespace
} // namespace penumbra::rhi
