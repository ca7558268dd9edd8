// The command-list rules, raised while recording, at the call that breaks them: pass state, bind-time usages
// and ranges, and at each draw the bound pipeline against the open pass and what is bound.

#include "penumbra/rhi/ValidatingDevice.hpp"

#include "DeviceLifetime.hpp"
#include "Rules.hpp"

#include "penumbra/rhi/Error.hpp"

#include <array>
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

// A dispatch's access to one binding, in the compute stage.
Use computeUse(const ShaderBinding& b)
{
    switch (b.kind) {
    case BindingKind::UniformBuffer:
        return {Stage::ComputeShader, Access::UniformRead};
    case BindingKind::SampledTexture:
        return {Stage::ComputeShader, Access::SampledRead};
    case BindingKind::StorageBuffer:
        return {Stage::ComputeShader,
                b.writes ? Access::StorageBufferRead | Access::StorageBufferWrite : Access::StorageBufferRead};
    case BindingKind::StorageTexture:
        break;
    }
    return {Stage::ComputeShader,
            b.writes ? Access::StorageImageRead | Access::StorageImageWrite : Access::StorageImageRead};
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

void ValidatingCommandList::record(const Barrier& barrier)
{
    if (!barrier.empty() && !barriersSuppressed_)
        apiBarrier(barrier);
}

void ValidatingCommandList::bindResource(std::uint32_t binding, const Texture& texture)
{
    if (binding >= resources_.size())
        resources_.resize(binding + 1);
    resources_[binding] = {&texture, graphicsUses(texture.desc()), &texture, nullptr};
}

void ValidatingCommandList::bindResource(std::uint32_t binding, const Buffer& buffer)
{
    if (binding >= resources_.size())
        resources_.resize(binding + 1);
    resources_[binding] = {&buffer, graphicsUses(buffer.desc()), nullptr, &buffer};
}

void ValidatingCommandList::orderDispatch(const Buffer* indirect)
{
    Barrier barrier;
    for (const ShaderBinding& b : computePipeline_->bindings()) {
        // With validation off nothing checks that each binding holds something; an empty one is left to the API.
        if (b.binding >= resources_.size() || !resources_[b.binding].object)
            continue;
        const Resource& r = resources_[b.binding];
        hazards_.use(r.object, r.graphics, computeUse(b), barrier);
    }
    if (indirect)
        hazards_.use(indirect, graphicsUses(indirect->desc()), {Stage::DrawIndirect, Access::IndirectRead}, barrier);
    record(barrier);
}

void ValidatingCommandList::forgetRecording()
{
    inPass_ = false;
    framebuffer_ = nullptr;
    pipeline_ = nullptr;
    computePipeline_ = nullptr;
    bound_.clear();
    resources_.clear();
    hazards_.reset();
    vertexSlots_ = 0;
    vertexBuffers_ = {};
    indexBufferObject_ = nullptr;
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
    record(hazards_.beginPass());
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
        vertexBuffers_[slot] = &buffer;
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
        indexBufferObject_ = &buffer;
        indexOffset_ = offset;
    }
    apiBindIndexBuffer(buffer, type, offset);
}

void ValidatingCommandList::bindUniformBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                              std::uint64_t size)
{
    if (validate_) {
        requireDevice("bindUniformBuffer");
        checkUniformRange("bindUniformBuffer", capabilities_, binding, buffer.desc(), offset, size);
        if (binding >= bound_.size())
            bound_.resize(binding + 1);
        bound_[binding] = {.set = true, .kind = BindingKind::UniformBuffer, .size = size};
        drawChecked_ = false;
    }
    bindResource(binding, buffer);
    apiBindUniformBuffer(binding, buffer, offset, size);
}

void ValidatingCommandList::bindTexture(std::uint32_t binding, const Texture& texture, const Sampler& sampler)
{
    if (validate_) {
        requireDevice("bindTexture");
        checkTextureBinding("bindTexture", capabilities_, texture, sampler);
        if (binding >= bound_.size())
            bound_.resize(binding + 1);
        bound_[binding] = {.set = true, .kind = BindingKind::SampledTexture};
        drawChecked_ = false;
    }
    bindResource(binding, texture);
    apiBindTexture(binding, texture, sampler);
}

void ValidatingCommandList::bindStorageBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                              std::uint64_t size)
{
    if (validate_) {
        requireDevice("bindStorageBuffer");
        checkStorageRange("bindStorageBuffer", capabilities_, binding, buffer.desc(), offset, size);
        if (binding >= bound_.size())
            bound_.resize(binding + 1);
        bound_[binding] = {.set = true, .kind = BindingKind::StorageBuffer, .size = size};
        drawChecked_ = false;
    }
    bindResource(binding, buffer);
    apiBindStorageBuffer(binding, buffer, offset, size);
}

void ValidatingCommandList::bindStorageTexture(std::uint32_t binding, const Texture& texture, std::uint32_t level)
{
    if (validate_) {
        requireDevice("bindStorageTexture");
        checkStorageTextureBinding("bindStorageTexture", texture, level);
        if (binding >= bound_.size())
            bound_.resize(binding + 1);
        bound_[binding] = {.set = true, .kind = BindingKind::StorageTexture, .texture = &texture.desc()};
        drawChecked_ = false;
    }
    bindResource(binding, texture);
    apiBindStorageTexture(binding, texture, level);
}

// The set's items were checked when it was created; here they only take their binding numbers.
void ValidatingCommandList::bindBindingSet(const BindingSet& set)
{
    if (validate_) {
        requireDevice("bindBindingSet");
        for (const BindingSetItem& item : set.items()) {
            if (item.binding >= bound_.size())
                bound_.resize(item.binding + 1);
            bound_[item.binding] = {.set = true,
                                    .kind = item.kind,
                                    .size = item.size,
                                    .texture = item.texture ? &item.texture->desc() : nullptr,
                                    .from = &set};
        }
        drawChecked_ = false;
    }
    for (const BindingSetItem& item : set.items()) {
        if (item.buffer)
            bindResource(item.binding, *item.buffer);
        else
            bindResource(item.binding, *item.texture);
    }
    apiBindBindingSet(set);
}

void ValidatingCommandList::apiBindBindingSet(const BindingSet& set)
{
    for (const BindingSetItem& item : set.items()) {
        switch (item.kind) {
        case BindingKind::UniformBuffer:
            apiBindUniformBuffer(item.binding, *item.buffer, item.offset, item.size);
            break;
        case BindingKind::SampledTexture:
            apiBindTexture(item.binding, *item.texture, *item.sampler);
            break;
        case BindingKind::StorageBuffer:
            apiBindStorageBuffer(item.binding, *item.buffer, item.offset, item.size);
            break;
        case BindingKind::StorageTexture:
            apiBindStorageTexture(item.binding, *item.texture, item.level);
            break;
        }
    }
}

void ValidatingCommandList::bindComputePipeline(const ComputePipeline& pipeline)
{
    if (validate_)
        requireDevice("bindComputePipeline");
    computePipeline_ = &pipeline;
    apiBindComputePipeline(pipeline);
}

void ValidatingCommandList::checkBindings(std::string_view what, const std::string& pipeline,
                                          const std::vector<ShaderBinding>& bindings)
{
    for (const ShaderBinding& b : bindings) {
        const Bound bound = b.binding < bound_.size() ? bound_[b.binding] : Bound{};
        if (bound.from && bound.kind != b.kind)
            throw Error(fmt::format("{}: binding set '{}' (layout '{}') holds a {} at binding {}, but pipeline '{}' "
                                    "declares a {} there ('{}'): the set's layout differs from the pipeline's",
                                    what, bound.from->debugName(), bound.from->layout().debugName,
                                    bindingKindName(bound.kind), b.binding, pipeline, bindingKindName(b.kind), b.name));
        if (!bound.set || bound.kind != b.kind)
            throw Error(fmt::format("{}: pipeline '{}' binding {} ('{}') needs a {}, but {}", what, pipeline, b.binding,
                                    b.name, bindingKindName(b.kind),
                                    bound.set ? fmt::format("a {} is bound", bound.kind == BindingKind::SampledTexture
                                                                                 ? std::string_view("texture")
                                                                                 : bindingKindName(bound.kind))
                                              : std::string("nothing is bound")));
        const bool block = b.kind == BindingKind::UniformBuffer || b.kind == BindingKind::StorageBuffer;
        if (block && bound.size < b.size)
            throw Error(fmt::format("{}: pipeline '{}' binding {} ('{}') is a {} block of {} bytes, but {} "
                                    "bytes are bound",
                                    what, pipeline, b.binding, b.name,
                                    b.kind == BindingKind::UniformBuffer ? "uniform" : "storage", b.size, bound.size));
        if (b.kind == BindingKind::StorageTexture && b.format && bound.texture->format != *b.format)
            throw Error(fmt::format("{}: pipeline '{}' binding {} ('{}') is a storage image of format {}, but "
                                    "texture '{}' is {}",
                                    what, pipeline, b.binding, b.name, formatName(*b.format), bound.texture->debugName,
                                    formatName(bound.texture->format)));
    }
}

void ValidatingCommandList::checkDispatch(std::string_view what)
{
    requireOutsidePass(what);
    if (!computePipeline_)
        throw Error(fmt::format("{}: no compute pipeline is bound; call bindComputePipeline() first", what));
    checkBindings(what, computePipeline_->desc().debugName, computePipeline_->bindings());
    checkDeclaredBindings(what, computePipeline_->bindings());
}

void ValidatingCommandList::dispatch(std::uint32_t x, std::uint32_t y, std::uint32_t z)
{
    if (validate_) {
        checkDispatch("dispatch");
        const std::array<std::uint32_t, 3> counts{x, y, z};
        for (std::size_t axis = 0; axis < 3; ++axis)
            if (counts[axis] > capabilities_.maxWorkgroupCount[axis])
                throw Error(fmt::format("dispatch: {} workgroups along {} exceed Capabilities::maxWorkgroupCount ({})",
                                        counts[axis], "xyz"[axis], capabilities_.maxWorkgroupCount[axis]));
    }
    orderDispatch(nullptr);
    apiDispatch(x, y, z);
}

void ValidatingCommandList::dispatchIndirect(const Buffer& buffer, std::uint64_t offset)
{
    if (validate_) {
        checkDispatch("dispatchIndirect");
        checkDrawIndirect("dispatchIndirect", buffer, offset, 3 * sizeof(std::uint32_t));
    }
    orderDispatch(&buffer);
    apiDispatchIndirect(buffer, offset);
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
    checkBindings(what, desc.debugName, pipeline_->bindings());
    for (const VertexAttribute& a : desc.vertexLayout.attributes)
        if (!(vertexSlots_ & (1u << a.buffer)))
            throw Error(fmt::format("{}: pipeline '{}' reads vertex buffer slot {}, which is not bound", what,
                                    desc.debugName, a.buffer));
    checkDeclaredBindings(what, pipeline_->bindings());
    checkDeclaredVertices(what);
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
        checkDeclared("drawIndexed", nullptr, indexBufferObject_, ResourceState::IndexBuffer, "index buffer");
    }
    apiDrawIndexed(indexCount, instanceCount, firstIndex, vertexOffset, firstInstance);
}

void ValidatingCommandList::checkDrawIndirect(std::string_view what, const Buffer& buffer, std::uint64_t offset,
                                              std::uint64_t size)
{
    checkBufferUsage(what, buffer.desc(), BufferUsage::Indirect, "Indirect");
    if (offset % 4 != 0)
        throw Error(fmt::format("{}: offset {} is not a multiple of 4", what, offset));
    checkBufferRange(fmt::format("{} arguments", what), buffer.desc(), offset, size);
    checkDeclared(what, nullptr, &buffer, ResourceState::IndirectArgument, "indirect arguments");
}

void ValidatingCommandList::drawIndirect(const Buffer& buffer, std::uint64_t offset)
{
    if (validate_) {
        checkDraw("drawIndirect");
        checkDrawIndirect("drawIndirect", buffer, offset, kDrawIndirectCommandBytes);
    }
    apiDrawIndirect(buffer, offset);
}

void ValidatingCommandList::drawIndexedIndirect(const Buffer& buffer, std::uint64_t offset)
{
    if (validate_) {
        checkDraw("drawIndexedIndirect");
        checkDrawIndirect("drawIndexedIndirect", buffer, offset, kDrawIndexedIndirectCommandBytes);
        checkIndexedIndirect("drawIndexedIndirect");
    }
    apiDrawIndexedIndirect(buffer, offset);
}

void ValidatingCommandList::checkIndexedIndirect(std::string_view what) const
{
    if (!indexBuffer_)
        throw Error(fmt::format("{}: no index buffer is bound; call bindIndexBuffer() first", what));
    // GL's DrawElementsIndirectCommand has no byte offset into the index buffer (GL 4.5 section 10.4): firstIndex
    // is the only start, so the same rule holds on every backend.
    if (indexOffset_ != 0)
        throw Error(fmt::format("{}: the index buffer is bound at offset {}; indirect indexed draws need offset 0 "
                                "(start with the arguments' firstIndex)",
                                what, indexOffset_));
    checkDeclared(what, nullptr, indexBufferObject_, ResourceState::IndexBuffer, "index buffer");
}

void ValidatingCommandList::checkDrawIndirectCount(std::string_view what, const Buffer& buffer, std::uint64_t offset,
                                                   const Buffer& count, std::uint64_t countOffset,
                                                   std::uint32_t maxDrawCount, std::uint64_t stride)
{
    checkDraw(what);
    checkDrawIndirect(what, buffer, offset, std::uint64_t(maxDrawCount) * stride);
    const std::string countWhat = fmt::format("{} count", what);
    checkBufferUsage(countWhat, count.desc(), BufferUsage::Indirect, "Indirect");
    if (countOffset % 4 != 0)
        throw Error(fmt::format("{}: offset {} is not a multiple of 4", countWhat, countOffset));
    checkBufferRange(countWhat, count.desc(), countOffset, sizeof(std::uint32_t));
    checkDeclared(what, nullptr, &count, ResourceState::IndirectArgument, "draw count");
}

void ValidatingCommandList::drawIndirectCount(const Buffer& buffer, std::uint64_t offset, const Buffer& count,
                                              std::uint64_t countOffset, std::uint32_t maxDrawCount)
{
    if (validate_)
        checkDrawIndirectCount("drawIndirectCount", buffer, offset, count, countOffset, maxDrawCount,
                               kDrawIndirectCommandBytes);
    apiDrawIndirectCount(buffer, offset, count, countOffset, maxDrawCount);
}

void ValidatingCommandList::drawIndexedIndirectCount(const Buffer& buffer, std::uint64_t offset, const Buffer& count,
                                                     std::uint64_t countOffset, std::uint32_t maxDrawCount)
{
    if (validate_) {
        checkDrawIndirectCount("drawIndexedIndirectCount", buffer, offset, count, countOffset, maxDrawCount,
                               kDrawIndexedIndirectCommandBytes);
        checkIndexedIndirect("drawIndexedIndirectCount");
    }
    apiDrawIndexedIndirectCount(buffer, offset, count, countOffset, maxDrawCount);
}

void ValidatingCommandList::copyBuffer(const Buffer& src, std::uint64_t srcOffset, Buffer& dst, std::uint64_t dstOffset,
                                       std::uint64_t size)
{
    if (validate_) {
        requireOutsidePass("copyBuffer");
        checkBufferRange("copyBuffer source", src.desc(), srcOffset, size);
        checkBufferRange("copyBuffer destination", dst.desc(), dstOffset, size);
        checkDeclared("copyBuffer", nullptr, &src, ResourceState::CopySource, "source");
        checkDeclared("copyBuffer", nullptr, &dst, ResourceState::CopyDestination, "destination");
    }
    Barrier barrier = hazards_.copy(&src, {Stage::Copy, Access::CopyRead});
    barrier.merge(hazards_.copy(&dst, {Stage::Copy, Access::CopyWrite}));
    record(barrier);
    apiCopyBuffer(src, srcOffset, dst, dstOffset, size);
}

void ValidatingCommandList::copyTexture(const Texture& src, std::uint32_t srcLayer, Texture& dst,
                                        std::uint32_t dstLayer)
{
    if (validate_) {
        requireOutsidePass("copyTexture");
        checkTextureCopy(src, srcLayer, dst, dstLayer);
        checkDeclared("copyTexture", &src, nullptr, ResourceState::CopySource, "source");
        checkDeclared("copyTexture", &dst, nullptr, ResourceState::CopyDestination, "destination");
    }
    Barrier barrier = hazards_.copy(&src, {Stage::Copy, Access::CopyRead});
    barrier.merge(hazards_.copy(&dst, {Stage::Copy, Access::CopyWrite}));
    record(barrier);
    apiCopyTexture(src, srcLayer, dst, dstLayer);
}

void ValidatingCommandList::copyTextureToBuffer(const Texture& src, std::uint32_t layer, std::uint32_t level,
                                                Buffer& dst, std::uint64_t dstOffset)
{
    if (validate_) {
        requireOutsidePass("copyTextureToBuffer");
        checkTextureReadback(src.desc(), layer, level, dst.desc(), dstOffset);
        checkDeclared("copyTextureToBuffer", &src, nullptr, ResourceState::CopySource, "source");
        checkDeclared("copyTextureToBuffer", nullptr, &dst, ResourceState::CopyDestination, "destination");
    }
    Barrier barrier = hazards_.copy(&src, {Stage::Copy, Access::CopyRead});
    barrier.merge(hazards_.copy(&dst, {Stage::Copy, Access::CopyWrite}));
    record(barrier);
    apiCopyTextureToBuffer(src, layer, level, dst, dstOffset);
}

void ValidatingCommandList::resolveTexture(const Texture& src, Texture& dst)
{
    if (validate_) {
        requireOutsidePass("resolveTexture");
        checkTextureResolve(src, dst);
        checkDeclared("resolveTexture", &src, nullptr, ResourceState::CopySource, "source");
        checkDeclared("resolveTexture", &dst, nullptr, ResourceState::CopyDestination, "destination");
    }
    Barrier barrier = hazards_.copy(&src, {Stage::Copy, Access::CopyRead});
    barrier.merge(hazards_.copy(&dst, {Stage::Copy, Access::CopyWrite}));
    record(barrier);
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
        hazards_.labelClosed(labels_.size());
        drawChecked_ = false; // the declared uses may have ended with the label
    }
    apiPopLabel();
}

void ValidatingCommandList::insertLabel(std::string_view name)
{
    if (validate_)
        requireDevice("insertLabel");
    apiInsertLabel(name);
}

} // namespace penumbra::rhi
