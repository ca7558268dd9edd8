#include "TextureSampling.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::render {
namespace {

rhi::Filter filter(scene::TextureFilter f)
{
    return f == scene::TextureFilter::Linear ? rhi::Filter::Linear : rhi::Filter::Nearest;
}

rhi::MipFilter mipFilter(scene::TextureMipFilter f)
{
    switch (f) {
    case scene::TextureMipFilter::None:
        return rhi::MipFilter::None;
    case scene::TextureMipFilter::Nearest:
        return rhi::MipFilter::Nearest;
    case scene::TextureMipFilter::Linear:
        return rhi::MipFilter::Linear;
    }
    return rhi::MipFilter::None;
}

rhi::AddressMode address(scene::TextureWrap wrap)
{
    switch (wrap) {
    case scene::TextureWrap::Repeat:
        return rhi::AddressMode::Repeat;
    case scene::TextureWrap::ClampToEdge:
        return rhi::AddressMode::ClampToEdge;
    case scene::TextureWrap::MirroredRepeat:
        return rhi::AddressMode::MirroredRepeat;
    }
    return rhi::AddressMode::Repeat;
}

} // namespace

AnisotropyChoice chooseAnisotropy(float requested, const rhi::Capabilities& caps)
{
    if (!(requested >= 1.0f))
        throw rhi::Error(
            fmt::format("FrameDesc::maxAnisotropy {} is below 1 (1 turns anisotropic filtering off)", requested));
    const float limit = caps.maxSamplerAnisotropy;
    if (requested <= limit)
        return {requested, std::nullopt};
    if (limit <= 1.0f)
        return {1.0f, fmt::format("textures are sampled without anisotropic filtering (maxAnisotropy {} asked): {} "
                                  "has none",
                                  requested, caps.device)};
    return {limit, fmt::format("textures are sampled with anisotropy {}, the limit of {} (maxAnisotropy {} asked)",
                               limit, caps.device, requested)};
}

rhi::SamplerDesc samplerDesc(const scene::TextureSampler& sampler, float anisotropy, const std::string& name)
{
    const bool trilinear =
        sampler.minFilter == scene::TextureFilter::Linear && sampler.mipFilter == scene::TextureMipFilter::Linear;
    return {.magFilter = filter(sampler.magFilter),
            .minFilter = filter(sampler.minFilter),
            .mipFilter = mipFilter(sampler.mipFilter),
            .addressU = address(sampler.wrapS),
            .addressV = address(sampler.wrapT),
            .maxAnisotropy = trilinear ? anisotropy : 1.0f,
            .debugName = name};
}

std::uint32_t mipLevelsFor(const scene::TextureImage& image)
{
    return image.sampler.mipFilter == scene::TextureMipFilter::None ? 1u : rhi::fullMipChain(image.width, image.height);
}

} // namespace penumbra::render
