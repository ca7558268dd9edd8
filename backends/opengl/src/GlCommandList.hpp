#pragma once

#include "GlPipeline.hpp"
#include "GlResources.hpp"
#include "penumbra/rhi/ValidatingDevice.hpp"

#include <optional>
#include <variant>
#include <vector>

namespace penumbra::opengl {

class GlOrientation;
class GlStateCache;

// Recorded commands, resolved to GL names at record time and replayed at submit.
namespace command {
struct BeginPass {
    const GlFramebuffer* framebuffer;
    std::optional<glm::vec4> clearColor;
    bool clearDepth;
};
struct EndPass {};
struct SetViewport {
    rhi::Viewport viewport;
};
struct SetScissor {
    rhi::Rect scissor;
};
struct SetDepthBias {
    rhi::DepthBias bias; // signed
};
struct BindPipeline {
    const GlPipeline* pipeline;
};
struct BindVertexBuffer {
    std::uint32_t slot;
    GLuint buffer;
    std::uint64_t offset;
};
struct BindIndexBuffer {
    GLuint buffer;
    GLenum type;
    std::uint64_t offset;
};
struct BindUniformBuffer {
    std::uint32_t binding;
    GLuint buffer;
    std::uint64_t offset;
    std::uint64_t size;
};
struct BindTexture {
    std::uint32_t unit;
    GLuint texture;
    GLuint sampler;
};
struct BindStorageBuffer {
    std::uint32_t binding;
    GLuint buffer;
    std::uint64_t offset;
    std::uint64_t size;
};
struct BindStorageTexture {
    std::uint32_t unit;
    GLuint texture;
    std::uint32_t level;
    GLenum format;
};
struct BindComputePipeline {
    GLuint program;
};
struct Dispatch {
    std::uint32_t x, y, z;
};
// Indirect commands: the arguments' buffer and offset.
struct DispatchIndirect {
    GLuint buffer;
    std::uint64_t offset;
};
struct DrawIndirect {
    GLuint buffer;
    std::uint64_t offset;
};
struct DrawIndexedIndirect {
    GLuint buffer;
    std::uint64_t offset;
};
// drawIndirectCount and drawIndexedIndirectCount; `native` where the driver reads the count itself.
struct DrawIndirectCount {
    GLuint buffer;
    std::uint64_t offset;
    GLuint count;
    std::uint64_t countOffset;
    std::uint32_t maxDrawCount;
    bool indexed;
    bool native;
};
struct Barrier {
    GLbitfield bits;
};
struct InsertLabel {
    std::string name;
};
struct Draw {
    std::uint32_t vertexCount, instanceCount, firstVertex, firstInstance;
};
struct DrawIndexed {
    std::uint32_t indexCount, instanceCount, firstIndex;
    std::int32_t vertexOffset;
    std::uint32_t firstInstance;
};
struct CopyBuffer {
    GLuint src;
    std::uint64_t srcOffset;
    GLuint dst;
    std::uint64_t dstOffset, size;
};
struct CopyTexture {
    const GlTexture* src;
    std::uint32_t srcLayer;
    const GlTexture* dst;
    std::uint32_t dstLayer;
};
struct CopyTextureToBuffer {
    const GlTexture* src;
    std::uint32_t layer;
    std::uint32_t level;
    const GlBuffer* dst;
    std::uint64_t dstOffset;
};
struct ResolveTexture {
    const GlTexture* src;
    const GlTexture* dst;
};
struct WriteTimestamp {
    GlTimestampQueries* queries;
    std::uint32_t index;
};
struct PushLabel {
    std::string name;
};
struct PopLabel {};

using Any = std::variant<BeginPass, EndPass, SetViewport, SetScissor, SetDepthBias, BindPipeline, BindVertexBuffer,
                         BindIndexBuffer, BindUniformBuffer, BindTexture, BindStorageBuffer, BindStorageTexture,
                         BindComputePipeline, Dispatch, DispatchIndirect, DrawIndirect, DrawIndexedIndirect,
                         DrawIndirectCount, Barrier, InsertLabel, Draw, DrawIndexed, CopyBuffer, CopyTexture,
                         CopyTextureToBuffer, ResolveTexture, WriteTimestamp, PushLabel, PopLabel>;
} // namespace command

// What replaying needs from the device.
struct GlReplayContext {
    const GlFunctions& gl;
    GlStateCache& cache;
    const GlOrientation& orientation;
    float clearDepth;
    std::uint64_t generation; // distinguishes submits for the per-VAO caches
    GLuint resolveRead, resolveDraw; // framebuffers for ResolveTexture
};

// Records into a vector and replays at submit, so buffer writes made before submit are seen
// (Vulkan's semantics). A list must not outlive the device that created it.
class GlCommandList final : public rhi::ValidatingCommandList {
public:
    GlCommandList(rhi::ValidatingDevice& device, const GlContext& context)
        : ValidatingCommandList(device), device_(device), context_(context)
    {
    }

    const GlContext& context() const { return context_; }
    // Runs every recorded command on the current context, then empties the list (also on error).
    void replay(const GlReplayContext& replay);

private:
    void apiBeginPass(const rhi::PassDesc& pass) override;
    void apiEndPass() override;
    void apiSetViewport(const rhi::Viewport& viewport) override;
    void apiSetScissor(const rhi::Rect& scissor) override;
    void apiSetDepthBias(const rhi::DepthBias& bias) override;
    void apiBindPipeline(const rhi::Pipeline& pipeline) override;
    void apiBindVertexBuffer(std::uint32_t slot, const rhi::Buffer& buffer, std::uint64_t offset) override;
    void apiBindIndexBuffer(const rhi::Buffer& buffer, rhi::IndexType type, std::uint64_t offset) override;
    void apiBindUniformBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                              std::uint64_t size) override;
    void apiBindTexture(std::uint32_t binding, const rhi::Texture& texture, const rhi::Sampler& sampler) override;
    void apiBindStorageBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                              std::uint64_t size) override;
    void apiBindStorageTexture(std::uint32_t binding, const rhi::Texture& texture, std::uint32_t level) override;
    void apiBindComputePipeline(const rhi::ComputePipeline& pipeline) override;
    void apiDispatch(std::uint32_t x, std::uint32_t y, std::uint32_t z) override;
    void apiDispatchIndirect(const rhi::Buffer& buffer, std::uint64_t offset) override;
    void apiDrawIndirect(const rhi::Buffer& buffer, std::uint64_t offset) override;
    void apiDrawIndexedIndirect(const rhi::Buffer& buffer, std::uint64_t offset) override;
    void apiDrawIndirectCount(const rhi::Buffer& buffer, std::uint64_t offset, const rhi::Buffer& count,
                              std::uint64_t countOffset, std::uint32_t maxDrawCount) override;
    void apiDrawIndexedIndirectCount(const rhi::Buffer& buffer, std::uint64_t offset, const rhi::Buffer& count,
                                     std::uint64_t countOffset, std::uint32_t maxDrawCount) override;
    void apiBarrier(const rhi::Barrier& barrier) override;
    void apiDraw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
                 std::uint32_t firstInstance) override;
    void apiDrawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                        std::int32_t vertexOffset, std::uint32_t firstInstance) override;
    void apiCopyBuffer(const rhi::Buffer& src, std::uint64_t srcOffset, rhi::Buffer& dst, std::uint64_t dstOffset,
                       std::uint64_t size) override;
    void apiCopyTexture(const rhi::Texture& src, std::uint32_t srcLayer, rhi::Texture& dst,
                        std::uint32_t dstLayer) override;
    void apiCopyTextureToBuffer(const rhi::Texture& src, std::uint32_t layer, std::uint32_t level, rhi::Buffer& dst,
                                std::uint64_t dstOffset) override;
    void apiResolveTexture(const rhi::Texture& src, rhi::Texture& dst) override;
    void apiWriteTimestamp(rhi::TimestampQueries& queries, std::uint32_t index) override;
    void apiPushLabel(std::string_view name) override;
    void apiPopLabel() override;
    void apiInsertLabel(std::string_view name) override;

    const rhi::Device& device_;
    const GlContext& context_;
    std::vector<command::Any> commands_;
};

} // namespace penumbra::opengl
