#pragma once

#include "penumbra/rhi/LiveObjects.hpp"
#include "penumbra/rhi/ResourceBarrier.hpp"

#include <cstdint>
#include <glm/vec4.hpp>
#include <optional>
#include <span>
#include <string_view>

namespace penumbra::rhi {

class BindingSet;
class Buffer;
class ComputePipeline;
class Framebuffer;
class Pipeline;
class Sampler;
class Texture;
class TimestampQueries;
struct DepthBias;

enum class IndexType : std::uint8_t { UInt16, UInt32 };

// Bytes of one drawIndirect command (four uint32) and one drawIndexedIndirect command (five): the strides of the
// count draws' packed commands.
inline constexpr std::uint32_t kDrawIndirectCommandBytes = 16;
inline constexpr std::uint32_t kDrawIndexedIndirectCommandBytes = 20;

// Pixels; y counts rows from the top of the render target on every backend.
struct Viewport {
    float x = 0.0f;
    float y = 0.0f;
    float width = 0.0f;
    float height = 0.0f;
};

// A scissor rectangle in pixels, rows counted from the top.
struct Rect {
    std::int32_t x = 0;
    std::int32_t y = 0;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

// What CommandList::beginPass draws into and clears.
struct PassDesc {
    const Framebuffer* framebuffer = nullptr;
    // Clear colour for every colour attachment; nullopt keeps their contents.
    std::optional<glm::vec4> clearColor = glm::vec4(0.0f);
    // Clears depth to Conventions::clearDepth() (the far plane); false keeps it.
    bool clearDepth = true;
};

// Hazards are the RHI's, not the user's: a list orders each access after the writes it depends on and each write after
// the accesses it would overwrite, with the narrowest barrier the APIs offer (Vulkan pipeline barriers, GL
// glMemoryBarrier), derived from what each dispatch binds and from the usages resources were created with. Passes,
// copies and readbacks that follow a dispatch see its writes, and a dispatch sees what earlier passes and copies
// wrote; the host sees a dispatch's writes to a buffer once submit returns.
//
// Records commands; Device::submit runs them in order and waits. After a submit the list is
// empty and records anew. Resources a list names must outlive its submission; the list must not
// outlive its device.
class CommandList : private LiveObject<ObjectKind::CommandList> {
public:
    virtual ~CommandList() = default;

    // A pass sets viewport and scissor to the whole framebuffer.
    virtual void beginPass(const PassDesc& pass) = 0;
    // Ends the pass; copies, resolves and submits happen outside passes.
    virtual void endPass() = 0;

    // The viewport of the next draws, rows counted from the top.
    virtual void setViewport(const Viewport& viewport) = 0;
    // The scissor of the next draws, rows counted from the top.
    virtual void setScissor(const Rect& scissor) = 0;
    // Binding a pipeline sets its DepthState::bias; this overrides it until the next bindPipeline.
    virtual void setDepthBias(const DepthBias& bias) = 0;

    // Draws use this pipeline; its formats must match the pass's framebuffer.
    virtual void bindPipeline(const Pipeline& pipeline) = 0;
    // The vertex buffer of a slot of the pipeline's VertexLayout.
    virtual void bindVertexBuffer(std::uint32_t slot, const Buffer& buffer, std::uint64_t offset = 0) = 0;
    // The index buffer of drawIndexed.
    virtual void bindIndexBuffer(const Buffer& buffer, IndexType type, std::uint64_t offset = 0) = 0;
    // offset must be a multiple of Capabilities::uniformBufferOffsetAlignment.
    virtual void bindUniformBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                   std::uint64_t size) = 0;
    // A texture and its sampler at a combined-sampler binding number.
    virtual void bindTexture(std::uint32_t binding, const Texture& texture, const Sampler& sampler) = 0;
    // A range of a BufferUsage::Storage buffer at a storage-block binding number; offset must be a multiple of
    // Capabilities::storageBufferOffsetAlignment, size at most Capabilities::maxStorageBufferRange.
    virtual void bindStorageBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                   std::uint64_t size) = 0;
    // One mip level of a TextureUsage::Storage texture at a storage-image binding number (imageLoad, imageStore).
    virtual void bindStorageTexture(std::uint32_t binding, const Texture& texture, std::uint32_t level = 0) = 0;

    // Binds every item of the set as its single bind call would (bindUniformBuffer, bindTexture, bindStorageBuffer,
    // bindStorageTexture), in one call, for draws and dispatches alike; a later bind or set replaces the bindings it
    // names. At each draw or dispatch, the pipeline's bindings at the set's numbers must be of the set layout's kinds
    // (numbers the pipeline does not declare are left unused).
    virtual void bindBindingSet(const BindingSet& set) = 0;

    // Dispatches use this pipeline; it is independent of bindPipeline's, and bindings are shared by both.
    virtual void bindComputePipeline(const ComputePipeline& pipeline) = 0;
    // Runs x * y * z workgroups of the bound compute pipeline, outside passes; each count is at most
    // Capabilities::maxWorkgroupCount.
    virtual void dispatch(std::uint32_t x, std::uint32_t y = 1, std::uint32_t z = 1) = 0;
    // dispatch with the counts read on the GPU from three uint32 at `offset` of a BufferUsage::Indirect buffer
    // (VkDispatchIndirectCommand; GL's DispatchIndirectCommand, GL 4.5 section 19), offset a multiple of 4.
    virtual void dispatchIndirect(const Buffer& buffer, std::uint64_t offset = 0) = 0;

    // Draws vertices in order, inside a pass.
    virtual void draw(std::uint32_t vertexCount, std::uint32_t instanceCount = 1, std::uint32_t firstVertex = 0,
                      std::uint32_t firstInstance = 0) = 0;
    // Draws through the bound index buffer, inside a pass.
    virtual void drawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount = 1, std::uint32_t firstIndex = 0,
                             std::int32_t vertexOffset = 0, std::uint32_t firstInstance = 0) = 0;

    // draw with its arguments read on the GPU from four uint32 at `offset` of a BufferUsage::Indirect buffer:
    // vertexCount, instanceCount, firstVertex, firstInstance (VkDrawIndirectCommand, GL's DrawArraysIndirectCommand);
    // offset a multiple of 4. The instances are not checked against per-instance vertex buffers: the CPU never sees
    // the count.
    virtual void drawIndirect(const Buffer& buffer, std::uint64_t offset = 0) = 0;
    // drawIndexed with five uint32 at `offset`: indexCount, instanceCount, firstIndex, vertexOffset (int32),
    // firstInstance (VkDrawIndexedIndirectCommand, GL's DrawElementsIndirectCommand); the index buffer is bound at
    // offset 0, since GL's command has no byte offset.
    virtual void drawIndexedIndirect(const Buffer& buffer, std::uint64_t offset = 0) = 0;
    // drawIndirect of up to maxDrawCount commands packed 16 bytes apart from `offset`, as many as the uint32 at
    // countOffset (a multiple of 4) of BufferUsage::Indirect buffer `count` says, read on the GPU
    // (vkCmdDrawIndirectCount, Vulkan 1.2 section 21.3; glMultiDrawArraysIndirectCount, GL 4.6 section 10.4). Where
    // Capabilities::drawIndirectCount is false the RHI emulates it with the same picture (docs/compute.md).
    virtual void drawIndirectCount(const Buffer& buffer, std::uint64_t offset, const Buffer& count,
                                   std::uint64_t countOffset, std::uint32_t maxDrawCount) = 0;
    // drawIndexedIndirect's commands packed 20 bytes apart, counted as drawIndirectCount's.
    virtual void drawIndexedIndirectCount(const Buffer& buffer, std::uint64_t offset, const Buffer& count,
                                          std::uint64_t countOffset, std::uint32_t maxDrawCount) = 0;

    // Copies outside passes. Texture copies take whole layers, every mip level, between textures of equal size,
    // format and level count; a texture-to-buffer copy writes one level of one layer in tightly packed rows,
    // row 0 (the top) first, depth only for D24S8.
    virtual void copyBuffer(const Buffer& src, std::uint64_t srcOffset, Buffer& dst, std::uint64_t dstOffset,
                            std::uint64_t size) = 0;
    // Copies one whole layer, every mip level, between textures of equal size, format and level count.
    virtual void copyTexture(const Texture& src, std::uint32_t srcLayer, Texture& dst, std::uint32_t dstLayer) = 0;
    // Copies one level of one layer into a buffer in tightly packed rows, row 0 (the top) first.
    virtual void copyTextureToBuffer(const Texture& src, std::uint32_t layer, std::uint32_t level, Buffer& dst,
                                     std::uint64_t dstOffset = 0) = 0;

    // Outside passes: averages the samples of each texel of multisampled colour texture `src` into level 0 of
    // single-sampled `dst`, a RenderTarget of the same size and format with one layer (Vulkan vkCmdResolveImage;
    // GL glBlitFramebuffer from a multisampled read framebuffer, GL 4.5 section 18.3.1). Depth is not resolved.
    virtual void resolveTexture(const Texture& src, Texture& dst) = 0;

    // Explicit barriers, outside passes: each resource leaves `before`, the state this list last declared for it
    // (Undefined the first time), for `after`; the list records the API barrier that orders the two (none where
    // neither writes or `before` is Undefined: earlier submissions have finished). A resource appears once per call,
    // and `after` needs the resource's usage (ShaderRead: TextureUsage::Sampled or Storage, or BufferUsage::Storage;
    // RenderTarget and DepthRead: TextureUsage::RenderTarget, DepthRead a depth format; ...).
    // The call also declares what the commands that follow use: until the next call, or until the label open at the
    // call closes (a frame graph's pass), the bindings, vertex, index and indirect buffers of every draw and dispatch
    // and the source and destination of every copy that this list has declared before must be declared by this call,
    // in a state that covers the access (ShaderWrite covers ShaderRead,
    // RenderTarget covers DepthRead), else the validation layer raises rhi::Error naming the label, the resource and
    // the use. Resources the list never declares keep the RHI's own hazard tracking (see above) alone.
    virtual void resourceBarriers(std::span<const ResourceBarrier> barriers) = 0;

    // Device::readTimestamps gives the values after submit.
    virtual void writeTimestamp(TimestampQueries& queries, std::uint32_t index) = 0;

    // A named group of the commands up to the matching popLabel, as graphics debuggers and validation messages show
    // it (Vulkan VK_EXT_debug_utils labels where the instance has the extension, Vulkan 1.3 section 50.2; GL 4.5
    // debug groups, section 20.6); groups nest, inside and outside passes. A list is submitted with every group it
    // opened closed.
    virtual void pushLabel(std::string_view name) = 0;
    // Closes the innermost open label.
    virtual void popLabel() = 0;
    // A single named marker at this point of the commands (vkCmdInsertDebugUtilsLabelEXT; GL glDebugMessageInsert
    // of type GL_DEBUG_TYPE_MARKER, GL 4.5 section 20.5), inside or outside passes.
    virtual void insertLabel(std::string_view name) = 0;
};

} // namespace penumbra::rhi
