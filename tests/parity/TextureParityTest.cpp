// Filtered texels across every configuration: a textured plane seen at a grazing angle, through every
// sampler configuration, must read back byte-identical on lavapipe and llvmpipe; CPU-made mip chains arrive
// unchanged everywhere.
#include "GpuTesting.hpp"

#include "penumbra/parity/GoogleTest.hpp"
#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/MipChain.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <array>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kWidth = 160;
constexpr std::uint32_t kHeight = 96;
constexpr std::uint32_t kTextureSize = 256; // 9 levels

// Level L's hue; its checker alternates the full colour and 60 % of it, so a pixel shows which levels it
// was filtered from whatever the blend of cells.
constexpr std::array<glm::vec3, 9> kLevelHues{
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0.5f, 0}, {0.5f, 0, 1}}};

struct SamplerCase {
    const char* name;
    rhi::SamplerDesc desc;
    bool anisotropic = false; // maxAnisotropy: the device's limit
};

const std::vector<SamplerCase>& samplerCases()
{
    using rhi::AddressMode;
    using rhi::Filter;
    using rhi::MipFilter;
    static const std::vector<SamplerCase> cases{
        {"nearest",
         {.magFilter = Filter::Nearest,
          .minFilter = Filter::Nearest,
          .addressU = AddressMode::Repeat,
          .addressV = AddressMode::Repeat}},
        {"nearest-mip-nearest",
         {.magFilter = Filter::Nearest,
          .minFilter = Filter::Nearest,
          .mipFilter = MipFilter::Nearest,
          .addressU = AddressMode::Repeat,
          .addressV = AddressMode::Repeat}},
        {"bilinear-mip-nearest",
         {.mipFilter = MipFilter::Nearest, .addressU = AddressMode::Repeat, .addressV = AddressMode::Repeat}},
        {"trilinear",
         {.mipFilter = MipFilter::Linear, .addressU = AddressMode::Repeat, .addressV = AddressMode::Repeat}},
        {"anisotropic",
         {.mipFilter = MipFilter::Linear, .addressU = AddressMode::Repeat, .addressV = AddressMode::Repeat},
         true},
        {"lod-clamped",
         {.mipFilter = MipFilter::Linear,
          .addressU = AddressMode::Repeat,
          .addressV = AddressMode::Repeat,
          .minLod = 1.0f,
          .maxLod = 3.0f}},
        {"mirrored",
         {.mipFilter = MipFilter::Linear,
          .addressU = AddressMode::MirroredRepeat,
          .addressV = AddressMode::MirroredRepeat}},
        {"clamped", {.mipFilter = MipFilter::Linear}},
    };
    return cases;
}

// Every level uploaded on its own: level L a checker of 4 x 4 cells in kLevelHues[L] (RGBA8_SRGB).
std::unique_ptr<rhi::Texture> levelCodedChecker(rhi::Device& device)
{
    const std::uint32_t levels = rhi::fullMipChain(kTextureSize, kTextureSize);
    auto texture = device.createTexture({.width = kTextureSize,
                                         .height = kTextureSize,
                                         .mipLevels = levels,
                                         .format = rhi::Format::RGBA8_SRGB,
                                         .debugName = "level-coded checker"});
    for (std::uint32_t level = 0; level < levels; ++level) {
        const std::uint32_t extent = rhi::mipExtent(kTextureSize, level);
        const std::uint32_t cell = std::max(extent / 4, 1u);
        std::vector<std::uint8_t> rgba;
        for (std::uint32_t y = 0; y < extent; ++y) {
            for (std::uint32_t x = 0; x < extent; ++x) {
                const float shade = (x / cell + y / cell) % 2 == 0 ? 1.0f : 0.6f;
                for (int c = 0; c < 3; ++c)
                    rgba.push_back(std::uint8_t(255.0f * shade * kLevelHues[level][c] + 0.5f));
                rgba.push_back(255);
            }
        }
        device.writeTexture(*texture, 0, level, std::as_bytes(std::span(rgba)));
    }
    return texture;
}

// A 6 x 40 plane at y = 0, its uv running 0..2 across and 0..8 along, seen from 0.6 above its near edge.
class GrazingPlane {
public:
    explicit GrazingPlane(rhi::Device& device) : device_(device)
    {
        vertex_ = device.createShader({rhi::ShaderStage::Vertex,
                                       R"(#version 450
#include "transform.glsl"
layout(std140, binding = 0) uniform View { mat4 viewProjection; } view;
layout(location = 0) out vec2 vUv;
void main() {
    const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
    const vec2 c = corners[gl_VertexIndex];
    vUv = c * vec2(2.0, 8.0);
    gl_Position = transformPoint(view.viewProjection, vec3(mix(-3.0, 3.0, c.x), 0.0, mix(-0.5, -40.5, c.y)));
}
)",
                                       "grazing_plane.vert",
                                       {{"transform.glsl", std::string(shaders::source("transform.glsl"))}}});
        fragment_ = device.createShader({rhi::ShaderStage::Fragment, R"(#version 450
layout(location = 0) in vec2 vUv;
layout(binding = 1) uniform sampler2D image;
layout(location = 0) out vec4 outColor;
void main() { outColor = texture(image, vUv); }
)",
                                         "grazing_plane.frag"});
        pipeline_ = device.createPipeline(
            {.vertex = vertex_.get(), .fragment = fragment_.get(), .colorTargets = {{.format = rhi::Format::RGBA8}}});
        uniforms_ = device.createBuffer({.size = sizeof(glm::mat4), .usage = rhi::BufferUsage::Uniform});
        const glm::mat4 view =
            glm::lookAt(glm::vec3(0.0f, 0.6f, 0.0f), glm::vec3(0.0f, 0.0f, -12.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        uniforms_->writeObject(
            device.conventions().perspective(glm::radians(50.0f), float(kWidth) / float(kHeight), 0.1f, 100.0f) * view);
        target_ = device.createTexture({.width = kWidth, .height = kHeight, .usage = rhi::TextureUsage::RenderTarget});
        const rhi::Attachment attachment{target_.get(), 0};
        framebuffer_ = device.createFramebuffer({.colors = {&attachment, 1}});
    }

    rhi::Image render(const rhi::Texture& texture, const rhi::Sampler& sampler)
    {
        auto commands = device_.createCommandList();
        commands->beginPass({.framebuffer = framebuffer_.get()});
        commands->bindPipeline(*pipeline_);
        commands->bindUniformBuffer(0, *uniforms_, 0, sizeof(glm::mat4));
        commands->bindTexture(1, texture, sampler);
        commands->draw(6);
        commands->endPass();
        device_.submit(*commands);
        return rhi::readTexture(device_, *target_);
    }

private:
    rhi::Device& device_;
    std::unique_ptr<rhi::Shader> vertex_, fragment_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
    std::unique_ptr<rhi::Buffer> uniforms_;
    std::unique_ptr<rhi::Texture> target_;
    std::unique_ptr<rhi::Framebuffer> framebuffer_;
};

// A 37 x 23 sRGB picture with alpha, odd in both sizes: the chain the loader would make for a texture.
std::vector<std::uint8_t> oddPicture()
{
    std::vector<std::uint8_t> rgba;
    for (std::uint32_t i = 0; i < 37u * 23u * 4u; ++i)
        rgba.push_back(std::uint8_t((i * 97 + (i / 148) * 31) % 256));
    return rgba;
}

std::string mipName(std::uint32_t level) { return fmt::format("mip-{}", level); }

// Per configuration: the plane through each sampler case (pictures named after it), and a CPU-made mip
// chain as read back, level by level ("mip-0", ...).
std::vector<parity::Picture> renderPlanesAndChain(rhi::Device& device, const rhi::NamedConfiguration&)
{
    std::vector<parity::Picture> pictures;
    GrazingPlane plane(device);
    auto texture = levelCodedChecker(device);
    for (const SamplerCase& c : samplerCases()) {
        rhi::SamplerDesc desc = c.desc;
        desc.maxAnisotropy = c.anisotropic ? device.capabilities().maxSamplerAnisotropy : 1.0f;
        auto sampler = device.createSampler(desc);
        pictures.push_back(parity::colorPicture(c.name, plane.render(*texture, *sampler)));
    }
    const std::vector<std::uint8_t> picture = oddPicture();
    auto chain = device.createTexture(
        {.width = 37, .height = 23, .mipLevels = rhi::fullMipChain(37, 23), .format = rhi::Format::RGBA8_SRGB});
    rhi::writeMipChain(device, *chain, 0, std::as_bytes(std::span(picture)));
    for (std::uint32_t level = 0; level < chain->desc().mipLevels; ++level)
        pictures.push_back(parity::colorPicture(mipName(level), rhi::readTexture(device, *chain, 0, level)));
    return pictures;
}

const std::vector<parity::ConfigurationRun>& renders()
{
    static const std::vector<parity::ConfigurationRun> runs = parity::renderConfigurations(renderPlanesAndChain);
    return runs;
}

const parity::ConfigurationRun& firstRendered()
{
    const parity::ConfigurationRun& first = renders().front();
    if (first.status != parity::ConfigurationRun::Status::Rendered)
        throw rhi::Error(fmt::format("{} did not render: {}", first.name(), first.message));
    return first;
}

// The judgement of the comparisons below: byte identity, as the harness's default thresholds.
::testing::AssertionResult identical(const rhi::Image& reference, const rhi::Image& image)
{
    const rhi::Conventions any(rhi::DepthRange::ZeroToOne, false);
    const parity::PictureComparison c = parity::comparePictures(parity::colorPicture("plane", reference), any,
                                                                parity::colorPicture("plane", image), any);
    if (c.pass())
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << parity::describe(c);
}

// The level whose hue is nearest the pixel's (by angle); -1 for the background. The target stores the
// sampled linear values, so the hues (sRGB-encoded in the texture) are compared decoded.
int levelOf(const rhi::Image& image, std::uint32_t x, std::uint32_t y)
{
    const Rgba p = pixel(image, x, y);
    const glm::vec3 c(p[0], p[1], p[2]);
    if (glm::length(c) < 1.0f)
        return -1;
    const auto closeness = [&](int level) {
        const glm::vec3 hue = kLevelHues[std::size_t(level)];
        const glm::vec3 linear(rhi::srgbToLinear(hue.r), rhi::srgbToLinear(hue.g), rhi::srgbToLinear(hue.b));
        return glm::dot(glm::normalize(c), glm::normalize(linear));
    };
    int best = 0;
    for (int level = 1; level < int(kLevelHues.size()); ++level)
        if (closeness(level) > closeness(best))
            best = level;
    return best;
}

// Every sampler case's plane, and every mip level, against the first configuration's: byte-identical.
TEST(TextureParity, GrazingPlaneIsByteIdenticalEverywhereInEverySamplerConfiguration)
{
    PENUMBRA_EXPECT_PARITY(renders(), {.pairing = parity::Pairing::AgainstReference});
}

// The picture shows mip selection at work: level 0 or 1 at the near edge, small levels towards the horizon,
// never a smaller level nearer the camera down the middle column.
TEST(TextureParity, MipLevelsGrowTowardsTheHorizon)
{
    const rhi::Image& image = firstRendered().picture("bilinear-mip-nearest").color;
    int nearest = -1, farthest = -1, previous = 0;
    for (std::uint32_t y = kHeight; y-- > 0;) {
        const int level = levelOf(image, kWidth / 2, y);
        if (level < 0)
            break; // above the plane's far edge
        EXPECT_GE(level, previous) << "row " << y;
        previous = level;
        nearest = nearest < 0 ? level : nearest;
        farthest = level;
    }
    std::cout << fmt::format(
        "[ texture parity ] levels down the middle column: {} at the near edge, {} at the far one\n", nearest,
        farthest);
    EXPECT_LE(nearest, 1);
    EXPECT_GE(farthest, 5);
}

// Each sampler setting reaches the driver: the pictures of settings that differ, differ.
TEST(TextureParity, EverySamplerSettingChangesThePicture)
{
    const parity::ConfigurationRun& planes = firstRendered();
    const std::pair<const char*, const char*> pairs[] = {{"nearest", "nearest-mip-nearest"},
                                                         {"nearest-mip-nearest", "bilinear-mip-nearest"},
                                                         {"bilinear-mip-nearest", "trilinear"},
                                                         {"trilinear", "anisotropic"},
                                                         {"trilinear", "lod-clamped"},
                                                         {"trilinear", "mirrored"},
                                                         {"trilinear", "clamped"}};
    for (const auto& [a, b] : pairs)
        EXPECT_FALSE(identical(planes.picture(a).color, planes.picture(b).color))
            << a << " and " << b << " gave the same picture";
}

// The negative control of the byte comparison: one pixel of a real render one level off in one channel.
TEST(TextureParity, ChangedFilteredPixelCatchesFault)
{
    const rhi::Image& reference = firstRendered().picture("anisotropic").color;
    rhi::Image changed = reference;
    std::byte& red = changed.bytes[(std::size_t(kWidth) * (kHeight - 10) + kWidth / 2) * 4];
    red = std::byte(std::uint8_t(red) ^ 1u);
    ASSERT_TRUE(identical(reference, reference));
    EXPECT_FALSE(identical(reference, changed));
}

// A chain made on the CPU reads back, level by level, as generateMipChain made it, in every configuration.
TEST(TextureParity, MipChainIsIdenticalEverywhere)
{
    const std::vector<std::uint8_t> picture = oddPicture();
    const auto expected = rhi::generateMipChain(rhi::Format::RGBA8_SRGB, 37, 23, rhi::fullMipChain(37, 23),
                                                std::as_bytes(std::span(picture)));
    for (const parity::ConfigurationRun& run : renders()) {
        if (run.status != parity::ConfigurationRun::Status::Rendered)
            continue; // GrazingPlane... reports it
        for (std::uint32_t level = 0; level < expected.size(); ++level)
            EXPECT_TRUE(run.picture(mipName(level)).color.bytes == expected[level]) << run.name() << " level " << level;
    }
}

} // namespace
} // namespace penumbra::testing
