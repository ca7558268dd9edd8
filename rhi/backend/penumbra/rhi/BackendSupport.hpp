#pragma once

// Shared by the backends, not meant for users: checks and conversions that must behave the
// same on every API, so they are written once here.

#include "penumbra/rhi/Device.hpp"

#include <string_view>

namespace penumbra::rhi {

// The texture must be Sampled; a linear filter is refused on a format the driver cannot filter linearly.
void checkTextureBinding(const Capabilities& caps, const Texture& texture, const Sampler& sampler);

// Size, layer count, mip level count, format support and cube rules of a texture description, against the
// driver's limits.
void checkTextureDesc(const Capabilities& caps, const TextureDesc& desc);

// LOD clamps and anisotropy of a sampler description, against the driver's limit.
void checkSamplerDesc(const Capabilities& caps, const SamplerDesc& desc);

// The level-of-detail range a backend gives its sampler. MipFilter::None becomes the nearest level with
// LOD in [0, 0.25]: level 0 only, yet minified texels still take the min filter (Vulkan 1.3, the note under
// VkSamplerCreateInfo on emulating GL_NEAREST and GL_LINEAR minification).
struct LodRange {
    float min = 0.0f;
    float max = 0.0f;
};
LodRange samplerLodRange(const SamplerDesc& desc);

// `what` (a command name) addresses level `level` of layer `layer`: both must exist.
void checkSubresource(std::string_view what, const TextureDesc& desc, std::uint32_t layer, std::uint32_t level);

// An upload of `size` bytes into one level of one layer: the subresource exists and the size is the level's.
void checkTextureUpload(const TextureDesc& desc, std::uint32_t layer, std::uint32_t level, std::uint64_t size);

// copyTextureToBuffer's rules: the subresource exists, the level fits the buffer at `offset`, and the offset
// is a multiple of the texel size (4 for depth formats; Vulkan 1.3, VUID-VkBufferImageCopy-bufferOffset-00193).
void checkTextureReadback(const TextureDesc& desc, std::uint32_t layer, std::uint32_t level, const BufferDesc& buffer,
                          std::uint64_t offset);

// copyTexture's rules: layers in range, equal size, format and level count, not a layer onto itself.
void checkTextureCopy(const Texture& src, std::uint32_t srcLayer, const Texture& dst, std::uint32_t dstLayer);

// A framebuffer's attachments must exist, share one size, be render targets, and have layers in range.
void checkFramebuffer(const FramebufferDesc& desc);

// A pipeline needs both shaders; their bindings must agree where both stages declare one.
void checkPipeline(const PipelineDesc& desc);

// The union of both stages' bindings, sorted by binding number.
std::vector<ShaderBinding> pipelineBindings(const PipelineDesc& desc);

// Bias in API terms: the requested away-from-viewer bias with the convention's sign.
DepthBias signedDepthBias(const Conventions& conventions, const DepthBias& bias);

// Bytes of one mip level of one layer as copied to a buffer: its width * height * texelSize.
std::uint64_t levelSize(const TextureDesc& desc, std::uint32_t level);

} // namespace penumbra::rhi
