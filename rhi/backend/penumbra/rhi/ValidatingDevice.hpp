#pragma once

// For backends: the base classes every backend's device and command list derive from. They are the RHI's one
// validation layer (rhi/src/validation): each public call checks the rules of the public headers and then
// calls the backend's api* function, so a backend holds only API calls and API failures.
//
// Why base classes and not a wrapper device around the backend's (NVRHI's validation layer, LLGL's DebugLayer):
// a wrapper hands users its own objects, so every backend entry point and the native-handle functions
// (penumbra/vulkan/Native.hpp, penumbra/opengl/Native.hpp) would first have to unwrap them, and each resource
// would exist twice. Here the user holds the backend's own objects; the checks still live in one place and a
// backend cannot skip them, since the public functions are final and only the api* ones are its to write.

#include "penumbra/rhi/BindingSet.hpp"
#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Hazards.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace penumbra::rhi {

class ValidatingCommandList;
struct DeviceLifetime;

class ValidatingDevice : public Device {
public:
    ~ValidatingDevice() override;

    std::unique_ptr<Buffer> createBuffer(const BufferDesc& desc) final;
    std::unique_ptr<Texture> createTexture(const TextureDesc& desc) final;
    void writeTexture(Texture& texture, std::uint32_t layer, std::uint32_t level,
                      std::span<const std::byte> data) final;
    std::unique_ptr<Sampler> createSampler(const SamplerDesc& desc) final;
    // Compiles with glslang (the conventions' header prepended), checks a compute shader's workgroup against the
    // limits before any driver sees it, then creates the backend's module.
    std::unique_ptr<Shader> createShader(const ShaderSource& source) final;
    std::unique_ptr<Pipeline> createPipeline(const PipelineDesc& desc) final;
    std::unique_ptr<ComputePipeline> createComputePipeline(const ComputePipelineDesc& desc) final;
    std::unique_ptr<BindingSetLayout> createBindingSetLayout(const BindingSetLayoutDesc& desc) final;
    std::unique_ptr<BindingSet> createBindingSet(const BindingSetDesc& desc) final;
    std::unique_ptr<Framebuffer> createFramebuffer(const FramebufferDesc& desc) final;
    std::unique_ptr<TimestampQueries> createTimestampQueries(std::uint32_t count) final;
    void submit(CommandList& commands) final;

protected:
    // `validate`: DeviceDesc::validateUsage.
    explicit ValidatingDevice(bool validate);

    virtual std::unique_ptr<Buffer> apiCreateBuffer(const BufferDesc& desc) = 0;
    virtual std::unique_ptr<Texture> apiCreateTexture(const TextureDesc& desc) = 0;
    virtual void apiWriteTexture(Texture& texture, std::uint32_t layer, std::uint32_t level,
                                 std::span<const std::byte> data) = 0;
    virtual std::unique_ptr<Sampler> apiCreateSampler(const SamplerDesc& desc) = 0;
    virtual std::unique_ptr<Shader> apiCreateShader(CompiledShader compiled) = 0;
    virtual std::unique_ptr<Pipeline> apiCreatePipeline(const PipelineDesc& desc) = 0;
    virtual std::unique_ptr<ComputePipeline> apiCreateComputePipeline(const ComputePipelineDesc& desc) = 0;
    // A checked set; by default the RHI's own, which the command list applies as single binds (apiBindBindingSet).
    virtual std::unique_ptr<BindingSet> apiCreateBindingSet(const BindingSetDesc& desc);
    virtual std::unique_ptr<Framebuffer> apiCreateFramebuffer(const FramebufferDesc& desc) = 0;
    virtual std::unique_ptr<TimestampQueries> apiCreateTimestampQueries(std::uint32_t count) = 0;
    virtual void apiSubmit(CommandList& commands) = 0;

private:
    friend class ValidatingCommandList;

    bool validate_;
    std::shared_ptr<DeviceLifetime> lifetime_;
};

class ValidatingCommandList : public CommandList {
public:
    ~ValidatingCommandList() override;

    void beginPass(const PassDesc& pass) final;
    void endPass() final;
    void setViewport(const Viewport& viewport) final;
    void setScissor(const Rect& scissor) final;
    void setDepthBias(const DepthBias& bias) final;
    void bindPipeline(const Pipeline& pipeline) final;
    void bindVertexBuffer(std::uint32_t slot, const Buffer& buffer, std::uint64_t offset) final;
    void bindIndexBuffer(const Buffer& buffer, IndexType type, std::uint64_t offset) final;
    void bindUniformBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset, std::uint64_t size) final;
    void bindTexture(std::uint32_t binding, const Texture& texture, const Sampler& sampler) final;
    void bindStorageBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset, std::uint64_t size) final;
    void bindStorageTexture(std::uint32_t binding, const Texture& texture, std::uint32_t level) final;
    void bindBindingSet(const BindingSet& set) final;
    void bindComputePipeline(const ComputePipeline& pipeline) final;
    void dispatch(std::uint32_t x, std::uint32_t y, std::uint32_t z) final;
    void dispatchIndirect(const Buffer& buffer, std::uint64_t offset) final;
    void drawIndirect(const Buffer& buffer, std::uint64_t offset) final;
    void drawIndexedIndirect(const Buffer& buffer, std::uint64_t offset) final;
    void drawIndirectCount(const Buffer& buffer, std::uint64_t offset, const Buffer& count, std::uint64_t countOffset,
                           std::uint32_t maxDrawCount) final;
    void drawIndexedIndirectCount(const Buffer& buffer, std::uint64_t offset, const Buffer& count,
                                  std::uint64_t countOffset, std::uint32_t maxDrawCount) final;
    void draw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
              std::uint32_t firstInstance) final;
    void drawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                     std::int32_t vertexOffset, std::uint32_t firstInstance) final;
    void copyBuffer(const Buffer& src, std::uint64_t srcOffset, Buffer& dst, std::uint64_t dstOffset,
                    std::uint64_t size) final;
    void copyTexture(const Texture& src, std::uint32_t srcLayer, Texture& dst, std::uint32_t dstLayer) final;
    void copyTextureToBuffer(const Texture& src, std::uint32_t layer, std::uint32_t level, Buffer& dst,
                             std::uint64_t dstOffset) final;
    void resolveTexture(const Texture& src, Texture& dst) final;
    void resourceBarriers(std::span<const ResourceBarrier> barriers) final;
    void writeTimestamp(TimestampQueries& queries, std::uint32_t index) final;
    void pushLabel(std::string_view name) final;
    void popLabel() final;
    void insertLabel(std::string_view name) final;

    // For negative controls only: with `suppressed`, the barriers the list derives are not recorded, so a test can
    // show that the API's synchronization validation reports the hazard each one prevents.
    void setBarriersSuppressed(bool suppressed) { barriersSuppressed_ = suppressed; }

    // Vertex buffer slots bindVertexBuffer takes: 0..maxVertexBuffers - 1.
    static constexpr std::uint32_t maxVertexBuffers = 16;

protected:
    explicit ValidatingCommandList(ValidatingDevice& device);

    virtual void apiBeginPass(const PassDesc& pass) = 0;
    virtual void apiEndPass() = 0;
    virtual void apiSetViewport(const Viewport& viewport) = 0;
    virtual void apiSetScissor(const Rect& scissor) = 0;
    virtual void apiSetDepthBias(const DepthBias& bias) = 0;
    virtual void apiBindPipeline(const Pipeline& pipeline) = 0;
    virtual void apiBindVertexBuffer(std::uint32_t slot, const Buffer& buffer, std::uint64_t offset) = 0;
    virtual void apiBindIndexBuffer(const Buffer& buffer, IndexType type, std::uint64_t offset) = 0;
    virtual void apiBindUniformBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                      std::uint64_t size) = 0;
    virtual void apiBindTexture(std::uint32_t binding, const Texture& texture, const Sampler& sampler) = 0;
    virtual void apiBindStorageBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                      std::uint64_t size) = 0;
    virtual void apiBindStorageTexture(std::uint32_t binding, const Texture& texture, std::uint32_t level) = 0;
    // Binds the set's items; by default through the single api bind calls, the table every backend applies.
    virtual void apiBindBindingSet(const BindingSet& set);
    virtual void apiBindComputePipeline(const ComputePipeline& pipeline) = 0;
    virtual void apiDispatch(std::uint32_t x, std::uint32_t y, std::uint32_t z) = 0;
    virtual void apiDispatchIndirect(const Buffer& buffer, std::uint64_t offset) = 0;
    virtual void apiDrawIndirect(const Buffer& buffer, std::uint64_t offset) = 0;
    virtual void apiDrawIndexedIndirect(const Buffer& buffer, std::uint64_t offset) = 0;
    // With Capabilities::drawIndirectCount false, the backend's emulation.
    virtual void apiDrawIndirectCount(const Buffer& buffer, std::uint64_t offset, const Buffer& count,
                                      std::uint64_t countOffset, std::uint32_t maxDrawCount) = 0;
    virtual void apiDrawIndexedIndirectCount(const Buffer& buffer, std::uint64_t offset, const Buffer& count,
                                             std::uint64_t countOffset, std::uint32_t maxDrawCount) = 0;
    // Records a barrier the hazard tracker derived (never empty), outside passes.
    virtual void apiBarrier(const Barrier& barrier) = 0;
    virtual void apiDraw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
                         std::uint32_t firstInstance) = 0;
    virtual void apiDrawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                                std::int32_t vertexOffset, std::uint32_t firstInstance) = 0;
    virtual void apiCopyBuffer(const Buffer& src, std::uint64_t srcOffset, Buffer& dst, std::uint64_t dstOffset,
                               std::uint64_t size) = 0;
    virtual void apiCopyTexture(const Texture& src, std::uint32_t srcLayer, Texture& dst, std::uint32_t dstLayer) = 0;
    virtual void apiCopyTextureToBuffer(const Texture& src, std::uint32_t layer, std::uint32_t level, Buffer& dst,
                                        std::uint64_t dstOffset) = 0;
    virtual void apiResolveTexture(const Texture& src, Texture& dst) = 0;
    virtual void apiWriteTimestamp(TimestampQueries& queries, std::uint32_t index) = 0;
    virtual void apiPushLabel(std::string_view name) = 0;
    virtual void apiPopLabel() = 0;
    virtual void apiInsertLabel(std::string_view name) = 0;

private:
    friend class ValidatingDevice;

    // What a binding number holds, for the checks at draw and dispatch time.
    struct Bound {
        bool set = false;
        BindingKind kind = BindingKind::UniformBuffer;
        std::uint64_t size = 0; // bytes of a uniform or storage range
        const TextureDesc* texture = nullptr; // a storage texture's description
        const BindingSet* from = nullptr; // the binding set that bound it, if one did
    };
    // What a binding number holds, for the hazard tracker (kept with validation off too).
    struct Resource {
        const void* object = nullptr;
        Use graphics; // its graphics uses
        const Texture* texture = nullptr; // the object, as what it is (for messages)
        const Buffer* buffer = nullptr;
    };

    // Every recording call starts here: the device must still exist.
    void requireDevice(std::string_view what) const;
    void requireOutsidePass(std::string_view what) const;
    void checkDraw(std::string_view what);
    void checkDrawIndirect(std::string_view what, const Buffer& buffer, std::uint64_t offset, std::uint64_t size);
    // drawIndirectCount's and drawIndexedIndirectCount's rules, `stride` bytes per command.
    void checkDrawIndirectCount(std::string_view what, const Buffer& buffer, std::uint64_t offset, const Buffer& count,
                                std::uint64_t countOffset, std::uint32_t maxDrawCount, std::uint64_t stride);
    void checkIndexedIndirect(std::string_view what) const;
    void checkDispatch(std::string_view what);
    void checkBindings(std::string_view what, const std::string& pipeline, const std::vector<ShaderBinding>& bindings);
    void bindResource(std::uint32_t binding, const Texture& texture);
    void bindResource(std::uint32_t binding, const Buffer& buffer);
    // Throws where the declared uses (resourceBarriers) do not cover an access of `texture` or `buffer` as `needed`;
    // `how` says which (BarrierRules.cpp).
    void checkDeclared(std::string_view what, const Texture* texture, const Buffer* buffer, ResourceState needed,
                       std::string_view how) const;
    // checkDeclared for every binding the pipeline declares and, for a draw, every vertex buffer it reads.
    void checkDeclaredBindings(std::string_view what, const std::vector<ShaderBinding>& bindings) const;
    void checkDeclaredVertices(std::string_view what) const;
    // The barrier before the bound compute pipeline's accesses (and `indirect`'s arguments, when given).
    void orderDispatch(const Buffer* indirect);
    void record(const Barrier& barrier);
    void forgetRecording();

    const Capabilities& capabilities_;
    bool validate_;
    std::shared_ptr<DeviceLifetime> lifetime_;
    bool inPass_ = false;
    const Framebuffer* framebuffer_ = nullptr;
    const Pipeline* pipeline_ = nullptr;
    const ComputePipeline* computePipeline_ = nullptr;
    std::vector<Bound> bound_;
    std::vector<Resource> resources_;
    HazardTracker hazards_;
    bool barriersSuppressed_ = false;
    std::uint32_t vertexSlots_ = 0; // bit per bound slot
    std::vector<std::string> labels_; // open, outermost first
    std::array<std::uint64_t, maxVertexBuffers> vertexBytes_{}; // per slot, the bound buffer's bytes past the offset
    std::array<const Buffer*, maxVertexBuffers> vertexBuffers_{};
    const Buffer* indexBufferObject_ = nullptr;
    bool indexBuffer_ = false;
    std::uint64_t indexOffset_ = 0;
    bool drawChecked_ = false; // nothing a draw depends on changed since the last checked draw
};

} // namespace penumbra::rhi
