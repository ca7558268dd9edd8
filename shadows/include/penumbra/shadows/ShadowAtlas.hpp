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

    std::uint32_t size() const { return size_; }
    rhi::Format format() const { return format_; }
    const rhi::Texture& texture() const { return *texture_; }
    rhi::Texture& texture() { return *texture_; } // to upload a baked map into
    const rhi::Framebuffer& framebuffer() const { return *framebuffer_; }
    const rhi::Sampler& sampler() const { return *sampler_; }

private:
    std::uint32_t size_;
    rhi::Format format_;
    std::unique_ptr<rhi::Texture> texture_;
    std::unique_ptr<rhi::Framebuffer> framebuffer_;
    std::unique_ptr<rhi::Sampler> sampler_;
};

} // namespace penumbra::shadows
