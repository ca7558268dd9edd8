#pragma once

// The stateless rules of the validation layer, one function per call they guard; ValidatingDevice and
// ValidatingCommandList call them first when DeviceDesc::validateUsage is on.

#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/ValidationRules.hpp"

#include <cstdint>
#include <span>
#include <string_view>

namespace penumbra::rhi {

// A draw of instanceCount instances from firstInstance: every per-instance vertex buffer of the pipeline holds its
// last instance's attributes. boundBytes[slot]: the bytes bound at the slot (the buffer's size past the offset).
void checkInstanceRange(std::string_view what, const PipelineDesc& desc, std::span<const std::uint64_t> boundBytes,
                        std::uint32_t instanceCount, std::uint32_t firstInstance);

// The buffer must have been created with `usage` (named `usageName` in the message).
void checkBufferUsage(std::string_view what, const BufferDesc& buffer, BufferUsage usage, std::string_view usageName);

// Size, layer count, mip level count, format support, sample count and cube rules of a texture description, against the
// driver's limits.
void checkTextureDesc(const Capabilities& caps, const TextureDesc& desc);

// LOD clamps and anisotropy of a sampler description, against the driver's limit.
void checkSamplerDesc(const Capabilities& caps, const SamplerDesc& desc);

// An upload of `size` bytes into one level of one layer: the subresource exists and the size is the level's.
void checkTextureUpload(const TextureDesc& desc, std::uint32_t layer, std::uint32_t level, std::uint64_t size);

// copyTextureToBuffer's rules: the subresource exists, the level fits the buffer at `offset`, and the offset
// is a multiple of the texel size (4 for depth formats; Vulkan 1.3, VUID-VkBufferImageCopy-bufferOffset-00193).
void checkTextureReadback(const TextureDesc& desc, std::uint32_t layer, std::uint32_t level, const BufferDesc& buffer,
                          std::uint64_t offset);

// One explicit barrier's rules (CommandList::resourceBarriers): one resource named, `after` a state its usages allow,
// `before` the state the list last declared for it (`declared`, Undefined where none).
void checkResourceBarrier(const ResourceBarrier& barrier, ResourceState declared);

// copyTexture's rules: layers in range, equal size, format and level count, not a layer onto itself.
void checkTextureCopy(const Texture& src, std::uint32_t srcLayer, const Texture& dst, std::uint32_t dstLayer);

// resolveTexture's rules: a multisampled colour source, a single-sampled single-layer RenderTarget destination
// of the same size and format.
void checkTextureResolve(const Texture& src, const Texture& dst);

// `what` binds the texture with the sampler: it must be Sampled; a linear filter is refused on a format the driver
// cannot filter linearly.
void checkTextureBinding(std::string_view what, const Capabilities& caps, const Texture& texture,
                         const Sampler& sampler);

// "uniform buffer", "texture and sampler", ...: what a binding of the kind holds, as messages name it.
std::string_view bindingKindName(BindingKind kind);

// `what` binds `size` bytes at `offset` of the buffer at a uniform block's binding: Uniform usage, 1 byte up to
// Capabilities::maxUniformBufferRange, inside the buffer, offset aligned.
void checkUniformRange(std::string_view what, const Capabilities& caps, std::uint32_t binding, const BufferDesc& buffer,
                       std::uint64_t offset, std::uint64_t size);
// The same for a storage block: Storage usage, maxStorageBufferRange, storageBufferOffsetAlignment.
void checkStorageRange(std::string_view what, const Capabilities& caps, std::uint32_t binding, const BufferDesc& buffer,
                       std::uint64_t offset, std::uint64_t size);
// `what` binds a level of the texture as a storage image: Storage usage, the level exists.
void checkStorageTextureBinding(std::string_view what, const Texture& texture, std::uint32_t level);

// Each binding number listed once.
void checkBindingSetLayout(const BindingSetLayoutDesc& desc);
// A layout, one item per binding of it and of its kind, each checked as its single bind call checks it.
void checkBindingSet(const Capabilities& caps, const BindingSetDesc& desc);

// A pipeline's PipelineDesc::bindingSetLayouts: none null, no binding number in two, and each of the shaders'
// `bindings` that one of them holds of the layout's kind.
void checkPipelineBindingSetLayouts(const std::string& pipeline, const std::vector<const BindingSetLayout*>& layouts,
                                    const std::vector<ShaderBinding>& bindings);

// A framebuffer's attachments must exist, share one size and sample count, be render targets, and have layers in range.
void checkFramebuffer(const FramebufferDesc& desc);

// At least one query, on a device with timestamps.
void checkTimestampQueries(const Capabilities& caps, std::uint32_t count);

// Both shaders in their stages, formats, colour target count, vertex layout slots, the features the depth
// state needs, bindings that agree between the stages, and the uniform layouts against reflection.
void checkPipeline(const Capabilities& caps, const PipelineDesc& desc);

// Each of desc.uniformLayouts against the std140 layout reflection gives the block of that name, each of
// desc.storageLayouts against the std430 layout of the storage block of that name.
void checkUniformLayouts(const PipelineDesc& desc);

// A compute shader's workgroup size and shared memory within the limits (checked when the shader is created: a GL
// driver refuses the shader itself).
void checkWorkgroup(const Capabilities& caps, const CompiledShader& shader);

// A compute shader in its stage, its layouts against reflection.
void checkComputePipeline(const ComputePipelineDesc& desc);

} // namespace penumbra::rhi
