#pragma once

// Shared by the backends, not meant for users: checks and conversions that must behave the
// same on every API, so they are written once here.

#include "penumbra/rhi/Device.hpp"

#include <string_view>

namespace penumbra::rhi {

// Refuses a linear sampler on a depth texture whose format the driver cannot filter linearly.
void checkTextureBinding(const Capabilities& caps, const Texture& texture, const Sampler& sampler);

// Size, layer count and cube rules of a texture description, against the driver's limits.
void checkTextureDesc(const Capabilities& caps, const TextureDesc& desc);

// A framebuffer's attachments must exist, share one size, be render targets, and have layers in range.
void checkFramebuffer(const FramebufferDesc& desc);

// A pipeline needs both shaders; their bindings must agree where both stages declare one.
void checkPipeline(const PipelineDesc& desc);

// The union of both stages' bindings, sorted by binding number.
std::vector<ShaderBinding> pipelineBindings(const PipelineDesc& desc);

// Bias in API terms: the requested away-from-viewer bias with the convention's sign.
DepthBias signedDepthBias(const Conventions& conventions, const DepthBias& bias);

// Bytes of one layer as copied to a buffer: width * height * texelSize.
std::uint64_t layerSize(const TextureDesc& desc);

} // namespace penumbra::rhi
