#pragma once

#include "penumbra/rhi/Device.hpp"

#include <cstdint>
#include <memory>

namespace penumbra::shadows {

// A square depth texture that shadow passes render into tile by tile and lit passes read with
// texelFetch (a nearest, non-comparison sampler: the lit shader builds its own comparisons).
class ShadowAtlas {
public:
    // Throws rhi::Error for a format that is not D16, D24S8 or D32F.
    ShadowAtlas(rhi::Device& device, std::uint32_t size, rhi::Format format, const std::string& debugName);

    // Texels per side.
    std::uint32_t size() const { return size_; }
    // The depth format.
    rhi::Format format() const { return format_; }
    // The depth texture.
    const rhi::Texture& texture() const { return *texture_; }
    // The depth texture, to upload a baked map into.
    rhi::Texture& texture() { return *texture_; }
    // The framebuffer the caster passes draw into.
    const rhi::Framebuffer& framebuffer() const { return *framebuffer_; }
    // The sampler the lit pass reads the atlas with.
    const rhi::Sampler& sampler() const { return *sampler_; }

private:
    std::uint32_t size_;
    rhi::Format format_;
    std::unique_ptr<rhi::Texture> texture_;
    std::unique_ptr<rhi::Framebuffer> framebuffer_;
    std::unique_ptr<rhi::Sampler> sampler_;
};

} // namespace penumbra::shadows
