#pragma once

#include "penumbra/rhi/Device.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace penumbra::shadows {

// Depth cube maps of point lights (PointShadowMode::CubeMap): one cube-map array, a framebuffer per
// face layer, and a nearest comparison sampler for samplerCubeArrayShadow lookups (hardware face
// selection; lavapipe cannot filter depth linearly, so every tap is a nearest comparison).
class ShadowCubes {
public:
    // Throws rhi::Error for a format that is not a depth format or a device without cube arrays.
    ShadowCubes(rhi::Device& device, std::uint32_t faceSize, std::uint32_t cubeCount, rhi::Format format);

    // Texels per face side.
    std::uint32_t faceSize() const { return faceSize_; }
    // Cubes in the array.
    std::uint32_t cubeCount() const { return cubeCount_; }
    // The depth format.
    rhi::Format format() const { return format_; }
    // The depth cube-map array.
    const rhi::Texture& texture() const { return *texture_; }
    // The framebuffer of one layer (6 x cube + face).
    const rhi::Framebuffer& framebuffer(std::uint32_t layer) const { return *framebuffers_.at(layer); }
    // The comparison sampler the lit pass reads the cubes with.
    const rhi::Sampler& sampler() const { return *sampler_; }
    // Nearest, no comparison: the stored depths themselves (samplerCubeArray), for blocker searches.
    const rhi::Sampler& depthSampler() const { return *depthSampler_; }

private:
    std::uint32_t faceSize_;
    std::uint32_t cubeCount_;
    rhi::Format format_;
    std::unique_ptr<rhi::Texture> texture_;
    std::vector<std::unique_ptr<rhi::Framebuffer>> framebuffers_;
    std::unique_ptr<rhi::Sampler> sampler_;
    std::unique_ptr<rhi::Sampler> depthSampler_;
};

} // namespace penumbra::shadows
