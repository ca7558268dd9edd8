#include "EnvironmentMaps.hpp"

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <glm/gtc/packing.hpp>

#include <chrono>
#include <cstring>
#include <vector>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kWorkgroupSize = 8; // environment_prefilter.comp's local size

// RGBA16F texels, alpha 1, as writeTexture takes them.
std::vector<std::byte> halfTexels(const std::vector<glm::vec4>& texels)
{
    std::vector<std::uint16_t> halves;
    halves.reserve(texels.size() * 4);
    for (const glm::vec4& t : texels)
        for (int c = 0; c < 4; ++c)
            halves.push_back(glm::packHalf1x16(t[c]));
    std::vector<std::byte> bytes(halves.size() * sizeof(std::uint16_t));
    std::memcpy(bytes.data(), halves.data(), bytes.size());
    return bytes;
}

// Level `level` of the image's box-filtered chain (each texel the mean of the 2 x 2 texels above it).
std::vector<std::vector<glm::vec4>> boxChain(const EnvironmentImage& image, std::uint32_t levels)
{
    std::vector<std::vector<glm::vec4>> chain(levels);
    chain[0].reserve(image.texels.size());
    for (const glm::vec3& t : image.texels)
        chain[0].emplace_back(t, 1.0f);
    std::uint32_t width = image.width;
    for (std::uint32_t m = 1; m < levels; ++m) {
        const std::uint32_t w = width / 2;
        const std::uint32_t h = w / 2;
        chain[m].resize(std::size_t(w) * h);
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                const auto at = [&](std::uint32_t dx, std::uint32_t dy) {
                    return chain[m - 1][std::size_t(2 * y + dy) * width + 2 * x + dx];
                };
                chain[m][std::size_t(y) * w + x] = (at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1)) * 0.25f;
            }
        width = w;
    }
    return chain;
}

} // namespace

EnvironmentMaps::EnvironmentMaps(rhi::Device& device) : device_(device)
{
    blank_ = device.createTexture({.format = rhi::Format::RGBA16F, .debugName = "environment stand-in"});
    device.writeTexture(*blank_, 0, 0, halfTexels({glm::vec4(0.0f)}));
    wrapSampler_ = device.createSampler(
        {.mipFilter = rhi::MipFilter::Linear, .addressU = rhi::AddressMode::Repeat, .debugName = "environment"});
    clampSampler_ = device.createSampler({.debugName = "environment BRDF"});
}

EnvironmentMaps::~EnvironmentMaps() = default;

std::optional<double> EnvironmentMaps::use(const std::shared_ptr<const EnvironmentImage>& image)
{
    if (image == image_)
        return std::nullopt;
    const auto start = std::chrono::steady_clock::now();
    if (image)
        prefilter(*image);
    image_ = image;
    if (!image)
        return std::nullopt;
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void EnvironmentMaps::prefilter(const EnvironmentImage& image)
{
    validate(image, "image");
    const EnvironmentImage resampled = image.width == kEnvironmentWidth && image.height == kEnvironmentHeight
                                           ? image
                                           : resampleEnvironment(image, kEnvironmentWidth, kEnvironmentHeight);
    diffuse_ = diffuseShaderCoefficients(projectSh9(resampled));
    if (!pipeline_) {
        auto shader = device_.createShader(
            shaders::load("environment_prefilter.comp",
                          {{"ENVIRONMENT_LEVELS", kEnvironmentLevels}, {"ENVIRONMENT_SAMPLES", kEnvironmentSamples}}));
        pipeline_ = device_.createComputePipeline({.compute = shader.get(), .debugName = "environment prefilter"});
        brdf_ = device_.createTexture({.width = kBrdfTableSize,
                                       .height = kBrdfTableSize,
                                       .format = rhi::Format::RGBA16F,
                                       .debugName = "environment BRDF table"});
        std::vector<glm::vec4> table;
        for (const glm::vec2& ab : brdfTable(kBrdfTableSize))
            table.emplace_back(ab, 0.0f, 1.0f);
        device_.writeTexture(*brdf_, 0, 0, halfTexels(table));
        const rhi::TextureDesc chain{.width = kEnvironmentWidth,
                                     .height = kEnvironmentHeight,
                                     .mipLevels = kEnvironmentLevels,
                                     .format = rhi::Format::RGBA16F};
        rhi::TextureDesc sourceDesc = chain;
        sourceDesc.debugName = "environment source";
        source_ = device_.createTexture(sourceDesc);
        rhi::TextureDesc specularDesc = chain;
        specularDesc.usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::Storage;
        specularDesc.debugName = "environment specular";
        specular_ = device_.createTexture(specularDesc);
    }
    const std::vector<std::vector<glm::vec4>> chain = boxChain(resampled, kEnvironmentLevels);
    for (std::uint32_t m = 0; m < kEnvironmentLevels; ++m)
        device_.writeTexture(*source_, 0, m, halfTexels(chain[m]));
    auto commands = device_.createCommandList();
    commands->pushLabel("environment prefilter");
    commands->bindComputePipeline(*pipeline_);
    commands->bindTexture(0, *source_, *wrapSampler_);
    for (std::uint32_t m = 0; m < kEnvironmentLevels; ++m) {
        commands->bindStorageTexture(1, *specular_, m);
        const std::uint32_t width = kEnvironmentWidth >> m;
        const std::uint32_t height = kEnvironmentHeight >> m;
        commands->dispatch((width + kWorkgroupSize - 1) / kWorkgroupSize,
                           (height + kWorkgroupSize - 1) / kWorkgroupSize);
    }
    commands->popLabel();
    device_.submit(*commands);
}

void EnvironmentMaps::bind(rhi::CommandList& commands) const
{
    commands.bindTexture(kLitEnvironmentSpecularBinding, image_ ? *specular_ : *blank_, *wrapSampler_);
    commands.bindTexture(kLitEnvironmentBrdfBinding, image_ ? *brdf_ : *blank_, *clampSampler_);
}

const rhi::Texture& EnvironmentMaps::specular() const
{
    if (!image_)
        throw rhi::Error("environment: no environment is in use, so there is no specular chain");
    return *specular_;
}

const rhi::Texture& EnvironmentMaps::source() const
{
    if (!image_)
        throw rhi::Error("environment: no environment is in use, so there is no source");
    return *source_;
}

} // namespace penumbra::render
