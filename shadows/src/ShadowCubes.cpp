#include "penumbra/shadows/ShadowCubes.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {

ShadowCubes::ShadowCubes(rhi::Device& device, std::uint32_t faceSize, std::uint32_t cubeCount, rhi::Format format)
    : faceSize_(faceSize), cubeCount_(cubeCount), format_(format)
{
    if (!rhi::isDepthFormat(format))
        throw rhi::Error(
            fmt::format("shadow cube maps: {} is not a depth format; use D16, D24S8 or D32F", rhi::formatName(format)));
    texture_ = device.createTexture({.width = faceSize,
                                     .height = faceSize,
                                     .layers = 6 * cubeCount,
                                     .cube = true,
                                     .format = format,
                                     .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                     .debugName = "point shadow cube maps"});
    for (std::uint32_t layer = 0; layer < 6 * cubeCount; ++layer)
        framebuffers_.push_back(device.createFramebuffer(
            {.depth = {texture_.get(), layer}, .debugName = fmt::format("point shadow cube face {}", layer)}));
    sampler_ = device.createSampler({.magFilter = rhi::Filter::Nearest,
                                     .minFilter = rhi::Filter::Nearest,
                                     .compare = true,
                                     .debugName = "point shadow cubes"});
    depthSampler_ = device.createSampler({.magFilter = rhi::Filter::Nearest,
                                          .minFilter = rhi::Filter::Nearest,
                                          .debugName = "point shadow cube depths"});
}

} // namespace penumbra::shadows
