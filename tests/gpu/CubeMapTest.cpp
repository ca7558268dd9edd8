#include "CubeScene.hpp"
#include "GpuTesting.hpp"

#include "penumbra/rhi/Error.hpp"

#include <glm/geometric.hpp>
#include <optional>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kFaceSize = 32;
const glm::vec3 kCentre(0.5f, -1.0f, 2.0f);

// Each face of the scene, seen from kCentre: a wall filling it (a dim colour) and a marker off
// centre towards +b and +c, longer along b than along c, so that a flipped, mirrored, rotated or
// transposed face puts it elsewhere. In front of each marker a white quad turned away from the
// centre must be culled.
constexpr glm::vec2 kMarkerB{0.1f, 0.7f};
constexpr glm::vec2 kMarkerC{0.2f, 0.5f};

Rgba markerColor(rhi::CubeFace face)
{
    constexpr Rgba colors[6] = {{255, 0, 0, 255},   {0, 255, 255, 255}, {0, 255, 0, 255},
                                {255, 0, 255, 255}, {0, 0, 255, 255},   {255, 255, 0, 255}};
    return colors[std::size_t(face)];
}

Rgba wallColor(rhi::CubeFace face)
{
    Rgba c = markerColor(face);
    for (int i = 0; i < 3; ++i)
        c[i] = std::uint8_t(c[i] / 4);
    return c;
}

glm::vec4 toVec4(Rgba c) { return glm::vec4(c[0], c[1], c[2], c[3]) / 255.0f; }

std::vector<CubeVertex> markerScene()
{
    std::vector<CubeVertex> triangles;
    for (rhi::CubeFace face : rhi::allCubeFaces)
        addCubeQuad(triangles, kCentre, face, 2.0f, {-1, 1}, {-1, 1}, toVec4(wallColor(face)));
    for (rhi::CubeFace face : rhi::allCubeFaces)
        addCubeQuad(triangles, kCentre, face, 1.0f, kMarkerB, kMarkerC, toVec4(markerColor(face)));
    for (rhi::CubeFace face : rhi::allCubeFaces)
        addCubeQuad(triangles, kCentre, face, 0.5f, {0.0f, 0.8f}, {0.1f, 0.6f}, glm::vec4(1.0f), false);
    return triangles;
}

// What the scene shows in direction d; nullopt within `margin` (face coordinates) of a marker edge.
std::optional<Rgba> expectedColor(const glm::vec3& d, float margin)
{
    const rhi::CubeFace face = majorFace(d);
    const CubeFaceFrame f = cubeFaceFrame(face);
    const glm::vec3 p = d / glm::dot(d, f.axis);
    const float b = glm::dot(p, f.b), c = glm::dot(p, f.c);
    auto near = [&](float v, glm::vec2 range) {
        return std::abs(v - range[0]) < margin || std::abs(v - range[1]) < margin;
    };
    if (near(b, kMarkerB) || near(c, kMarkerC))
        return std::nullopt;
    const bool inside = b > kMarkerB[0] && b < kMarkerB[1] && c > kMarkerC[0] && c < kMarkerC[1];
    return inside ? markerColor(face) : wallColor(face);
}

class CubeMapTest : public GpuTest {
protected:
    std::unique_ptr<rhi::Texture> renderMarkerCube()
    {
        auto cube = device->createTexture({.width = kFaceSize,
                                           .height = kFaceSize,
                                           .layers = 6,
                                           .cube = true,
                                           .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                           .debugName = "marker cube"});
        CubeFaceRenderer(*device, rhi::Format::RGBA8, 0.1f, 10.0f).render(*cube, 0, kCentre, markerScene());
        return cube;
    }
};

TEST_F(CubeMapTest, FaceReadbacksMatchTheCubeSamplingTable)
{
    auto cube = renderMarkerCube();
    const std::string picture = savePicture(cubeStrip(*device, *cube, 0), configuration() + "/cube-faces");
    for (rhi::CubeFace face : rhi::allCubeFaces) {
        const rhi::Image image = rhi::readTexture(*device, *cube, rhi::cubeLayer(0, face));
        int compared = 0, wrong = 0;
        for (std::uint32_t y = 0; y < kFaceSize; ++y)
            for (std::uint32_t x = 0; x < kFaceSize; ++x) {
                const std::optional<Rgba> expected =
                    expectedColor(cubeTexelDirection(face, x, y, kFaceSize), 1.5f * 2.0f / kFaceSize);
                if (!expected)
                    continue;
                ++compared;
                wrong += pixel(image, x, y) != *expected;
            }
        EXPECT_GT(compared, int(kFaceSize * kFaceSize) / 2);
        EXPECT_EQ(wrong, 0) << "face " << int(face) << ": texels unlike the scene in their sampling direction, see "
                            << picture;
    }
}

TEST_F(CubeMapTest, SamplingFindsEachMarkerInItsDirection)
{
    auto cube = renderMarkerCube();
    auto sampler = device->createSampler(
        {.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest, .debugName = "cube"});
    // Per face, in face coordinates (b, c): the marker, its mirror images in b and in c, a point the
    // marker transposed would cover, the marker near its corner, and the wall near the face's edge.
    const glm::vec2 probesPerFace[] = {{0.4f, 0.35f}, {-0.4f, 0.35f}, {0.4f, -0.35f},
                                       {0.3f, 0.62f}, {0.62f, 0.43f}, {0.93f, 0.35f}};
    std::vector<glm::vec4> directions;
    std::vector<Rgba> expected;
    for (rhi::CubeFace face : rhi::allCubeFaces)
        for (glm::vec2 bc : probesPerFace) {
            const CubeFaceFrame f = cubeFaceFrame(face);
            const glm::vec3 d = 3.0f * (f.axis + bc.x * f.b + bc.y * f.c);
            directions.emplace_back(d, 0.0f);
            expected.push_back(expectedColor(d, 0.0f).value());
        }
    const rhi::Image sampled = sampleCubeProbes(*device, *cube, *sampler, "samplerCubeArray",
                                                "outColor = texture(cubeTexture, probe.direction[i]);", directions);
    for (std::size_t i = 0; i < directions.size(); ++i)
        EXPECT_EQ(pixel(sampled, std::uint32_t(i), 0), expected[i])
            << "probe " << i << " (face " << i / 6 << "): " << describe(pixel(sampled, std::uint32_t(i), 0));
}

TEST_F(CubeMapTest, FaceLayersCopyAndUploadLikeArrayLayers)
{
    auto cube = renderMarkerCube();
    const std::uint32_t layer = rhi::cubeLayer(0, rhi::CubeFace::NegativeY);
    const rhi::Image face = rhi::readTexture(*device, *cube, layer);

    auto plain = device->createTexture({.width = kFaceSize, .height = kFaceSize, .debugName = "plain copy"});
    auto commands = device->createCommandList();
    commands->copyTexture(*cube, layer, *plain, 0);
    device->submit(*commands);
    EXPECT_TRUE(rhi::readTexture(*device, *plain).bytes == face.bytes);

    auto twoCubes = device->createTexture(
        {.width = kFaceSize, .height = kFaceSize, .layers = 12, .cube = true, .debugName = "two cubes"});
    device->writeTexture(*twoCubes, rhi::cubeLayer(1, rhi::CubeFace::PositiveZ), 0, face.bytes);
    commands->copyTexture(*cube, layer, *twoCubes, rhi::cubeLayer(1, rhi::CubeFace::NegativeX));
    device->submit(*commands);
    EXPECT_TRUE(rhi::readTexture(*device, *twoCubes, rhi::cubeLayer(1, rhi::CubeFace::PositiveZ)).bytes == face.bytes);
    EXPECT_TRUE(rhi::readTexture(*device, *twoCubes, rhi::cubeLayer(1, rhi::CubeFace::NegativeX)).bytes == face.bytes);
}

TEST_F(CubeMapTest, BadCubeDescriptionsAreRefusedByName)
{
    auto expectRefused = [&](const rhi::TextureDesc& desc, const char* rule) {
        try {
            device->createTexture(desc);
            ADD_FAILURE() << desc.debugName << " was accepted";
        } catch (const rhi::Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(desc.debugName), std::string::npos) << message;
            EXPECT_NE(message.find(rule), std::string::npos) << message;
        }
    };
    expectRefused({.width = 8, .height = 8, .layers = 8, .cube = true, .debugName = "eight-layer cube"},
                  "multiple of 6");
    expectRefused({.width = 8, .height = 4, .layers = 6, .cube = true, .debugName = "oblong cube"}, "square");
}

} // namespace
} // namespace penumbra::testing
