#include "CubeScene.hpp"
#include "GpuTesting.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Image.hpp"

#include <cmath>
#include <glm/geometric.hpp>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kShadowFaceSize = 32;
constexpr float kNear = 0.1f, kFar = 10.0f;
const glm::vec3 kLight(-1.0f, 2.0f, 0.5f);

// Two point-light cubes in one depth cube array (12 layers; each depth format), lit from kLight. Cube 0: on every
// face an occluder plane at distance 1 covers the half b > 0; cube 1: at distance 2, the half c > 0.
struct Occluders {
    float distance;
    glm::vec2 bRange;
    glm::vec2 cRange;
};
constexpr Occluders kOccluders[2] = {{1.0f, {0.0f, 1.0f}, {-1.0f, 1.0f}}, {2.0f, {-1.0f, 1.0f}, {0.0f, 1.0f}}};

std::vector<CubeVertex> occluderScene(const Occluders& o)
{
    std::vector<CubeVertex> triangles;
    for (rhi::CubeFace face : rhi::allCubeFaces)
        addCubeQuad(triangles, kLight, face, o.distance, o.bRange, o.cRange, glm::vec4(1.0f));
    return triangles;
}

bool occluded(const Occluders& o, float b, float c)
{
    return b > o.bRange[0] && b < o.bRange[1] && c > o.cRange[0] && c < o.cRange[1];
}

// How far a stored depth may be from the exact window depth: rounding to the format.
float depthTolerance(rhi::Format format)
{
    switch (format) {
    case rhi::Format::D16:
        return 1.0f / 65535.0f;
    case rhi::Format::D24S8:
        return 1.0f / 16777215.0f;
    default:
        return 1e-6f;
    }
}

class CubeShadowTest : public GpuTest, public ::testing::WithParamInterface<rhi::Format> {
protected:
    void SetUp() override
    {
        GpuTest::SetUp();
        map = device->createTexture({.width = kShadowFaceSize,
                                     .height = kShadowFaceSize,
                                     .layers = 12,
                                     .cube = true,
                                     .format = GetParam(),
                                     .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                     .debugName = "point shadow cubes"});
        CubeFaceRenderer renderer(*device, GetParam(), kNear, kFar);
        for (std::uint32_t cube = 0; cube < 2; ++cube)
            renderer.render(*map, cube, kLight, occluderScene(kOccluders[cube]));
        projection = renderer.projection();
    }

    std::unique_ptr<rhi::Texture> map;
    glm::mat4 projection{1.0f};
};

TEST_P(CubeShadowTest, FaceDepthReadbacksMatchTheCubeSamplingTable)
{
    const rhi::Conventions& conventions = device->conventions();
    const float margin = 1.5f * 2.0f / kShadowFaceSize;
    for (std::uint32_t cube = 0; cube < 2; ++cube)
        for (rhi::CubeFace face : rhi::allCubeFaces) {
            const rhi::DepthImage depth = rhi::readDepth(*device, *map, rhi::cubeLayer(cube, face));
            const float occluderDepth = conventions.windowDepth(projection, kOccluders[cube].distance);
            const CubeFaceFrame f = cubeFaceFrame(face);
            int wrong = 0;
            for (std::uint32_t y = 0; y < kShadowFaceSize; ++y)
                for (std::uint32_t x = 0; x < kShadowFaceSize; ++x) {
                    const glm::vec3 d = cubeTexelDirection(face, x, y, kShadowFaceSize);
                    const float b = glm::dot(d, f.b), c = glm::dot(d, f.c);
                    if (std::abs(b) < margin || std::abs(c) < margin)
                        continue; // the occluders' edges
                    const float expected = occluded(kOccluders[cube], b, c) ? occluderDepth : conventions.clearDepth();
                    wrong += std::abs(depth.at(x, y) - expected) > depthTolerance(GetParam());
                }
            EXPECT_EQ(wrong, 0) << "cube " << cube << " face " << int(face);
        }
}

TEST_P(CubeShadowTest, ComparisonLookupsAgreeWithTheReferenceDepths)
{
    // Per cube and face: receivers 2 % nearer and 2 % farther than the occluder plane, behind the
    // occluder and beside it. Reference depth: the face projection's window depth at the receiver's
    // major-axis distance.
    std::vector<glm::vec4> directions;
    std::vector<float> references;
    std::vector<bool> expectLit;
    for (std::uint32_t cube = 0; cube < 2; ++cube)
        for (rhi::CubeFace face : rhi::allCubeFaces)
            for (bool behind : {true, false})
                for (float scale : {0.98f, 1.02f}) {
                    const CubeFaceFrame f = cubeFaceFrame(face);
                    const glm::vec2 bc =
                        cube == 0 ? glm::vec2(behind ? 0.5f : -0.5f, 0.3f) : glm::vec2(0.3f, behind ? 0.5f : -0.5f);
                    const glm::vec3 d = scale * kOccluders[cube].distance * (f.axis + bc.x * f.b + bc.y * f.c);
                    directions.emplace_back(d, float(cube));
                    references.push_back(device->conventions().windowDepth(projection, rhi::cubeFaceViewDepth(d)));
                    expectLit.push_back(!(behind && scale > 1.0f));
                }
    auto sampler = device->createSampler({.magFilter = rhi::Filter::Nearest,
                                          .minFilter = rhi::Filter::Nearest,
                                          .compare = true,
                                          .debugName = "cube shadow"});
    const rhi::Image lit =
        sampleCubeProbes(*device, *map, *sampler, "samplerCubeArrayShadow",
                         "outColor = vec4(texture(cubeTexture, probe.direction[i], probe.reference[i].x));", directions,
                         references);
    for (std::size_t i = 0; i < directions.size(); ++i)
        EXPECT_EQ(pixel(lit, std::uint32_t(i), 0)[0], expectLit[i] ? 255 : 0)
            << "probe " << i << ": cube " << i / 24 << ", face " << i / 4 % 6 << (i % 4 < 2 ? ", behind" : ", beside")
            << (i % 2 ? " the occluder, 2 % farther" : " the occluder, 2 % nearer");
}

TEST_P(CubeShadowTest, LinearComparisonFilteringFollowsTheCapability)
{
    auto linear = device->createSampler({.magFilter = rhi::Filter::Linear,
                                         .minFilter = rhi::Filter::Linear,
                                         .compare = true,
                                         .debugName = "linear cube"});
    auto commands = device->createCommandList();
    if (device->capabilities().supportsLinearFilter(GetParam())) {
        EXPECT_NO_THROW(commands->bindTexture(0, *map, *linear));
        return;
    }
    EXPECT_THROW(commands->bindTexture(0, *map, *linear), rhi::UnsupportedError);
}

INSTANTIATE_TEST_SUITE_P(, CubeShadowTest, ::testing::Values(rhi::Format::D32F, rhi::Format::D16, rhi::Format::D24S8),
                         [](const ::testing::TestParamInfo<rhi::Format>& format) {
                             return std::string(rhi::formatName(format.param));
                         });

} // namespace
} // namespace penumbra::testing
