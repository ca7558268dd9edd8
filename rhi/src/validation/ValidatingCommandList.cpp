// The command-list rules, raised while recording, at the call that breaks them: pass state, bind-time usages
// and ranges, and at each draw the bound pipeline against the open pass and what is bound.

#include "penumbra/rhi/ValidatingDevice.hpp"

#include "DeviceLifetime.hpp"
#include "Rules.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::rhi {
namespace {

std::string describe(const AttachmentFormats& formats)
{
    std::string text;
    for (Format f : formats.colors)
        text += (text.empty() ? "" : ", ") + std::string(formatName(f));
    if (formats.depth)
        text += (text.empty() ? "depth " : ", depth ") + std::string(formatName(*formats.depth));
    return text.empty() ? "no attachments" : text;
}

bool rendersTo(const PipelineDesc& desc, const AttachmentFormats& formats)
{
    if (desc.colorTargets.size() != formats.colors.size() || desc.depthFormat != formats.depth)
        return false;
    for (std::size_t i = 0; i < formats.colors.size(); ++i)
        if (desc.colorTargets[i].format != formats.colors[i])
            return false;
    return true;
}

AttachmentFormats pipelineFormats(const PipelineDesc& desc)
{
    AttachmentFormats formats{{}, desc.depthFormat};
    for (const ColorTarget& c : desc.colorTargets)
        formats.colors.push_back(c.format);
    return formats;
}

} // namespace

ValidatingCommandList::ValidatingCommandList(ValidatingDevice& device)
    : capabilities_(device.capabilities()), validate_(device.validate_), lifetime_(device.lifetime_)
{
    std::lock_guard lock(lifetime_->mutex);
    lifetime_->lists.push_back(this);
}

ValidatingCommandList::~ValidatingCommandList()
{
    std::lock_guard lock(lifetime_->mutex);
    std::erase(lifetime_->lists, this);
}

void ValidatingCommandList::requireDevice(std::string_view what) const
{
    if (!lifetime_->deviceAlive())
        throw Error(fmt::format("{}: the device that created this command list was destroyed", what));
}

void ValidatingCommandList::requireOutsidePass(std::string_view what) const
{
    requireDevice(what);
    if (inPass_)
        throw Error(fmt::format("{}: not allowed inside a pass; call endPass() first", what));
}

void ValidatingCommandList::forgetRecording()
{
    inPass_ = false;
    framebuffer_ = nullptr;
    pipeline_ = nullptr;
    bound_.clear();
    vertexSlots_ = 0;
    indexBuffer_ = false;
    drawChecked_ = false;
    labels_.clear();
}

void ValidatingCommandList::beginPass(const PassDesc& pass)
{
    if (validate_) {
        requireDevice("beginPass");
        if (inPass_)
            throw Error("beginPass: a pass is already open; call endPass() first");
        if (!pass.framebuffer)
            throw Error("beginPass: PassDesc::framebuffer is null");
        inPass_ = true;
        framebuffer_ = pass.framebuffer;
        drawChecked_ = false;
    }
    apiBeginPass(pass);
}

void ValidatingCommandList::endPass()
{
    if (validate_) {
        requireDevice("endPass");
        if (!inPass_)
            throw Error("endPass: no pass is open");
        inPass_ = false;
        framebuffer_ = nullptr;
    }
    apiEndPass();
}

void ValidatingCommandList::setViewport(const Viewport& viewport)
{
    if (validate_)
        requireDevice("setViewport");
    apiSetViewport(viewport);
}

void ValidatingCommandList::setScissor(const Rect& scissor)
{
    if (validate_)
        requireDevice("setScissor");
    apiSetScissor(scissor);
}

void ValidatingCommandList::setDepthBias(const DepthBias& bias)
{
    if (validate_) {
        requireDevice("setDepthBias");
        if (bias.clamp != 0.0f && !capabilities_.depthBiasClamp)
            throw UnsupportedError(
                fmt::format("setDepthBias: depth bias clamp is not supported by {}", capabilities_.device));
    }
    apiSetDepthBias(bias);
}

void ValidatingCommandList::bindPipeline(const Pipeline& pipeline)
{
    if (validate_) {
        requireDevice("bindPipeline");
        pipeline_ = &pipeline;
        drawChecked_ = false;
    }
    apiBindPipeline(pipeline);
}

void ValidatingCommandList::bindVertexBuffer(std::uint32_t slot, const Buffer& buffer, std::uint64_t offset)
{
    if (validate_) {
        requireDevice("bindVertexBuffer");
        if (slot >= maxVertexBuffers)
            throw Error(fmt::format("bindVertexBuffer: slot {} is outside 0..{}", slot, maxVertexBuffers - 1));
        checkBufferUsage("bindVertexBuffer", buffer.desc(), BufferUsage::Vertex, "Vertex");
        checkBufferRange("bindVertexBuffer", buffer.desc(), offset, 0);
        vertexSlots_ |= 1u << slot;
        vertexBytes_[slot] = buffer.desc().size - offset;
        drawChecked_ = false;
    }
    apiBindVertexBuffer(slot, buffer, offset);
}

void ValidatingCommandList::bindIndexBuffer(const Buffer& buffer, IndexType type, std::uint64_t offset)
{
    if (validate_) {
        requireDevice("bindIndexBuffer");
        checkBufferUsage("bindIndexBuffer", buffer.desc(), BufferUsage::Index, "Index");
        checkBufferRange("bindIndexBuffer", buffer.desc(), offset, 0);
        const std::uint64_t indexSize = type == IndexType::UInt16 ? 2 : 4;
        if (offset % indexSize != 0)
            throw Error(fmt::format("bindIndexBuffer: offset {} is not a multiple of the index size, {} bytes", offset,
                                    indexSize));
        indexBuffer_ = true;
    }
    apiBindIndexBuffer(buffer, type, offset);
}

void ValidatingCommandList::bindUniformBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                              std::uint64_t size)
{
    if (validate_) {
        requireDevice("bindUniformBuffer");
        checkBufferUsage("bindUniformBuffer", buffer.desc(), BufferUsage::Uniform, "Uniform");
        if (size == 0)
            throw Error(fmt::format("bindUniformBuffer: binding {}: a uniform range needs at least 1 byte", binding));
        if (size > capabilities_.maxUniformBufferRange)
            throw Error(fmt::format("bindUniformBuffer: binding {}: {} bytes exceed "
                                    "Capabilities::maxUniformBufferRange ({})",
                                    binding, size, capabilities_.maxUniformBufferRange));
        checkBufferRange("bindUniformBuffer", buffer.desc(), offset, size);
        if (offset % capabilities_.uniformBufferOffsetAlignment != 0)
            throw Error(fmt::format("bindUniformBuffer: offset {} is not a multiple of "
                                    "Capabilities::uniformBufferOffsetAlignment ({})",
                                    offset, capabilities_.uniformBufferOffsetAlignment));
        if (binding >= bound_.size())
            bound_.resize(binding + 1);
        bound_[binding] = {.uniform = true, .size = size};
        drawChecked_ = false;
    }
    apiBindUniformBuffer(binding, buffer, offset, size);
}

void ValidatingCommandList::bindTexture(std::uint32_t binding, const Texture& texture, const Sampler& sampler)
{
    if (validate_) {
        requireDevice("bindTexture");
        checkTextureBinding(capabilities_, texture, sampler);
        if (binding >= bound_.size())
            bound_.resize(binding + 1);
        bound_[binding] = {.texture = true};
        drawChecked_ = false;
    }
    apiBindTexture(binding, texture, sampler);
}

void ValidatingCommandList::checkDraw(std::string_view what)
{
    requireDevice(what);
    if (!inPass_)
        throw Error(fmt::format("{}: not inside a pass; call beginPass() first", what));
    if (!pipeline_)
        throw Error(fmt::format("{}: no pipeline is bound; call bindPipeline() first", what));
    if (drawChecked_)
        return;
    const PipelineDesc& desc = pipeline_->desc();
    if (desc.samples != framebuffer_->formats().samples)
        throw Error(fmt::format("{}: pipeline '{}' draws with {} sample(s), but the pass's framebuffer has {}", what,
                                desc.debugName, desc.samples, framebuffer_->formats().samples));
    if (!rendersTo(desc, framebuffer_->formats()))
        throw Error(fmt::format("{}: pipeline '{}' renders to {}, but the pass's framebuffer has {}", what,
                                desc.debugName, describe(pipelineFormats(desc)), describe(framebuffer_->formats())));
    for (const ShaderBinding& b : pipeline_->bindings()) {
        const Bound bound = b.binding < bound_.size() ? bound_[b.binding] : Bound{};
        const bool uniform = b.kind == BindingKind::UniformBuffer;
        if (uniform ? !bound.uniform : !bound.texture)
            throw Error(fmt::format("{}: pipeline '{}' binding {} ('{}') needs a {}, but {}", what, desc.debugName,
                                    b.binding, b.name, uniform ? "uniform buffer" : "texture and sampler",
                                    bound.uniform   ? "a uniform buffer is bound"
                                    : bound.texture ? "a texture is bound"
                                                    : "nothing is bound"));
        if (uniform && bound.size < b.size)
            throw Error(fmt::format("{}: pipeline '{}' binding {} ('{}') is a uniform block of {} bytes, but {} "
                                    "bytes are bound",
                                    what, desc.debugName, b.binding, b.name, b.size, bound.size));
    }
    for (const VertexAttribute& a : desc.vertexLayout.attributes)
        if (!(vertexSlots_ & (1u << a.buffer)))
            throw Error(fmt::format("{}: pipeline '{}' reads vertex buffer slot {}, which is not bound", what,
                                    desc.debugName, a.buffer));
    drawChecked_ = true;
}

void ValidatingCommandList::draw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
                                 std::uint32_t firstInstance)
{
    if (validate_) {
        checkDraw("draw");
        checkInstanceRange("draw", pipeline_->desc(), vertexBytes_, instanceCount, firstInstance);
    }
    apiDraw(vertexCount, instanceCount, firstVertex, firstInstance);
}

void ValidatingCommandList::drawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                                        std::int32_t vertexOffset, std::uint32_t firstInstance)
{
    if (validate_) {
        checkDraw("drawIndexed");
        checkInstanceRange("drawIndexed", pipeline_->desc(), vertexBytes_, instanceCount, firstInstance);
        if (!indexBuffer_)
            throw Error("drawIndexed: no index buffer is bound; call bindIndexBuffer() first");
    }
    apiDrawIndexed(indexCount, instanceCount, firstIndex, vertexOffset, firstInstance);
}

void ValidatingCommandList::copyBuffer(const Buffer& src, std::uint64_t srcOffset, Buffer& dst, std::uint64_t dstOffset,
                                       std::uint64_t size)
{
    if (validate_) {
        requireOutsidePass("copyBuffer");
        checkBufferRange("copyBuffer source", src.desc(), srcOffset, size);
        checkBufferRange("copyBuffer destination", dst.desc(), dstOffset, size);
    }
    apiCopyBuffer(src, srcOffset, dst, dstOffset, size);
}

void ValidatingCommandList::copyTexture(const Texture& src, std::uint32_t srcLayer, Texture& dst,
                                        std::uint32_t dstLayer)
{
    if (validate_) {
        requireOutsidePass("copyTexture");
        checkTextureCopy(src, srcLayer, dst, dstLayer);
    }
    apiCopyTexture(src, srcLayer, dst, dstLayer);
}

void ValidatingCommandList::copyTextureToBuffer(const Texture& src, std::uint32_t layer, std::uint32_t level,
                                                Buffer& dst, std::uint64_t dstOffset)
{
    if (validate_) {
        requireOutsidePass("copyTextureToBuffer");
        checkTextureReadback(src.desc(), layer, level, dst.desc(), dstOffset);
    }
    apiCopyTextureToBuffer(src, layer, level, dst, dstOffset);
}

void ValidatingCommandList::resolveTexture(const Texture& src, Texture& dst)
{
    if (validate_) {
        requireOutsidePass("resolveTexture");
        checkTextureResolve(src, dst);
    }
    apiResolveTexture(src, dst);
}

void ValidatingCommandList::writeTimestamp(TimestampQueries& queries, std::uint32_t index)
{
    if (validate_) {
        requireDevice("writeTimestamp");
        if (index >= queries.count())
            throw Error(fmt::format("writeTimestamp: index {} is out of range [0, {}]", index, queries.count() - 1));
    }
    apiWriteTimestamp(queries, index);
}

void ValidatingCommandList::pushLabel(std::string_view name)
{
    if (validate_) {
        requireDevice("pushLabel");
        labels_.emplace_back(name);
    }
    apiPushLabel(name);
}

void ValidatingCommandList::popLabel()
{
    if (validate_) {
        requireDevice("popLabel");
        if (labels_.empty())
            throw Error("popLabel: no label is open");
        labels_.pop_back();
    }
    apiPopLabel();
}

} // namespace penumbra::rhi
