#pragma once

// Shared by the backends, not meant for users: conversions that must behave the same on every API, so they
// are written once here. The checks are the validation layer's (ValidatingDevice.hpp).

#include "penumbra/rhi/Device.hpp"

#include <string_view>

namespace penumbra::rhi {

// The level-of-detail range a backend gives its sampler. MipFilter::None becomes the nearest level with
// LOD in [0, 0.25]: level 0 only, yet minified texels still take the min filter (Vulkan 1.3, the note under
// VkSamplerCreateInfo on emulating GL_NEAREST and GL_LINEAR minification).
struct LodRange {
    float min = 0.0f;
    float max = 0.0f;
};
LodRange samplerLodRange(const SamplerDesc& desc);

// The union of both stages' bindings, sorted by binding number; throws Error when the stages give one
// binding number different kinds.
std::vector<ShaderBinding> pipelineBindings(const PipelineDesc& desc);

// Bias in API terms: the requested away-from-viewer bias with the convention's sign.
DepthBias signedDepthBias(const Conventions& conventions, const DepthBias& bias);

// Bytes of one mip level of one layer as copied to a buffer: its width * height * texelSize.
std::uint64_t levelSize(const TextureDesc& desc, std::uint32_t level);

} // namespace penumbra::rhi
