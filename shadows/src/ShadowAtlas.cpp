#include "penumbra/shadows/ShadowAtlas.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {

ShadowAtlas::ShadowAtlas(rhi::Device& device, std::uint32_t size, rhi::Format format, const std::string& debugName)
    : size_(size), format_(format)
{
    if (!rhi::isDepthFormat(format))
        throw rhi::Error(fmt::format("shadow atlas '{}': {} is not a depth format; use D16, D24S8 or D32F", debugName,
                                     rhi::formatName(format)));
    texture_ = device.createTexture({.width = size,
                                     .height = size,
                                     .format = format,
                                     .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                     .debugName = debugName});
    framebuffer_ = device.createFramebuffer({.depth = {texture_.get(), 0}, .debugName = debugName});
    sampler_ = device.createSampler(
        {.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest, .debugName = debugName + " texels"});
}

} // namespace penumbra::shadows
