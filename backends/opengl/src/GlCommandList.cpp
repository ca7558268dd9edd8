#include "GlCommandList.hpp"

#include "GlFormats.hpp"
#include "GlOrientation.hpp"
#include "GlStateCache.hpp"
#include "penumbra/rhi/BackendSupport.hpp"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>

namespace penumbra::opengl {
namespace {

constexpr std::uint32_t maxVertexBuffers = rhi::ValidatingCommandList::maxVertexBuffers;

// Replays one list; lives for one submit and tracks what the recorded commands bound.
class Replayer {
public:
    explicit Replayer(const GlReplayContext& context) : r_(context), gl_(context.gl), cache_(context.cache) {}

    void operator()(const command::BeginPass& c)
    {
        const GlFramebuffer& framebuffer = *c.framebuffer;
        const GLuint fb = framebuffer.name();
        const rhi::Rect full{0, 0, framebuffer.width(), framebuffer.height()};
        cache_.bindDrawFramebuffer(fb);
        // Clears obey the scissor and the write masks: open them to the whole framebuffer first.
        cache_.enable(GlStateCache::Cap::ScissorTest, true);
        cache_.scissor(r_.orientation.scissor(full));
        if (c.clearColor) {
            for (GLuint i = 0; i < framebuffer.colorCount(); ++i) {
                cache_.colorMask(i, {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE});
                gl_.ClearNamedFramebufferfv(fb, GL_COLOR, GLint(i), &(*c.clearColor)[0]);
            }
        }
        if (c.clearDepth && framebuffer.hasDepth()) {
            cache_.depthMask(GL_TRUE);
            gl_.ClearNamedFramebufferfv(fb, GL_DEPTH, 0, &r_.clearDepth);
        }
        if (pipeline_)
            applyWriteMasks(pipeline_->state());
        cache_.viewport(r_.orientation.viewport({0.0f, 0.0f, float(full.width), float(full.height)}));
    }

    // GL has no pass object: the framebuffer stays bound until the next pass binds another.
    void operator()(const command::EndPass&) {}
    void operator()(const command::SetViewport& c) { cache_.viewport(r_.orientation.viewport(c.viewport)); }
    void operator()(const command::SetScissor& c) { cache_.scissor(r_.orientation.scissor(c.scissor)); }
    void operator()(const command::SetDepthBias& c) { cache_.polygonOffset(c.bias); }

    void operator()(const command::BindPipeline& c)
    {
        pipeline_ = c.pipeline;
        const GlFixedState& s = pipeline_->state();
        cache_.useProgram(pipeline_->program());
        cache_.bindVertexArray(pipeline_->vertexArray());
        cache_.enable(GlStateCache::Cap::DepthTest, s.depthTest);
        cache_.depthFunc(s.depthFunc);
        cache_.enable(GlStateCache::Cap::DepthClamp, s.depthClamp);
        cache_.enable(GlStateCache::Cap::CullFace, s.cull);
        cache_.cullFace(s.cullFace);
        cache_.polygonOffset(s.bias);
        for (GLuint i = 0; i < s.targets.size(); ++i) {
            const GlBlendTarget& t = s.targets[i];
            cache_.blend(i, t.enable, t.srcColor, t.dstColor, t.colorEquation, t.srcAlpha, t.dstAlpha, t.alphaEquation);
        }
        applyWriteMasks(s);
    }

    void operator()(const command::BindVertexBuffer& c) { vertexBuffers_[c.slot] = {c.buffer, c.offset}; }

    void operator()(const command::BindIndexBuffer& c)
    {
        indexBuffer_ = c.buffer;
        indexType_ = c.type;
        indexOffset_ = c.offset;
    }

    void operator()(const command::BindUniformBuffer& c)
    {
        cache_.uniformBuffer(c.binding, c.buffer, GLintptr(c.offset), GLsizeiptr(c.size));
    }

    void operator()(const command::BindTexture& c) { cache_.texture(c.unit, c.texture, c.sampler); }

    void operator()(const command::BindStorageBuffer& c)
    {
        gl_.BindBufferRange(GL_SHADER_STORAGE_BUFFER, c.binding, c.buffer, GLintptr(c.offset), GLsizeiptr(c.size));
    }

    void operator()(const command::BindStorageTexture& c)
    {
        gl_.BindImageTexture(c.unit, c.texture, GLint(c.level), GL_FALSE, 0, GL_READ_WRITE, c.format);
    }

    void operator()(const command::BindComputePipeline& c) { computeProgram_ = c.program; }

    void operator()(const command::Dispatch& c)
    {
        cache_.useProgram(computeProgram_);
        gl_.DispatchCompute(c.x, c.y, c.z);
    }

    void operator()(const command::DispatchIndirect& c)
    {
        cache_.useProgram(computeProgram_);
        gl_.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, c.buffer);
        gl_.DispatchComputeIndirect(GLintptr(c.offset));
    }

    // GL's gl_InstanceID leaves out the base instance, which SPIRV-Cross adds from a uniform; the arguments are on
    // the GPU, so gl_InstanceIndex of an indirect draw counts from 0 (docs/compute.md).
    void operator()(const command::DrawIndirect& c)
    {
        prepareDraw(0);
        gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, c.buffer);
        gl_.DrawArraysIndirect(pipeline_->state().primitive, reinterpret_cast<const void*>(std::uintptr_t(c.offset)));
    }

    void operator()(const command::DrawIndexedIndirect& c)
    {
        prepareDraw(0);
        bindIndexBufferToVertexArray();
        gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, c.buffer);
        gl_.DrawElementsIndirect(pipeline_->state().primitive, indexType_,
                                 reinterpret_cast<const void*>(std::uintptr_t(c.offset)));
    }

    void operator()(const command::DrawIndirectCount& c)
    {
        prepareDraw(0);
        if (c.indexed)
            bindIndexBufferToVertexArray();
        gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, c.buffer);
        const GLenum mode = pipeline_->state().primitive;
        const void* commands = reinterpret_cast<const void*>(std::uintptr_t(c.offset));
        if (c.native) {
            gl_.BindBuffer(GL_PARAMETER_BUFFER, c.count);
            if (c.indexed)
                gl_.MultiDrawElementsIndirectCount(mode, indexType_, commands, GLintptr(c.countOffset),
                                                   GLsizei(c.maxDrawCount), 0);
            else
                gl_.MultiDrawArraysIndirectCount(mode, commands, GLintptr(c.countOffset), GLsizei(c.maxDrawCount), 0);
            return;
        }
        // The emulation: GL runs commands in order, so the count is read here once every earlier command has written
        // it; shader stores need GL_BUFFER_UPDATE_BARRIER_BIT before a read through glGetBufferSubData (GL 4.5
        // section 7.12.2). The read waits for the GPU, which is the emulation's cost.
        gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::uint32_t drawn = 0;
        gl_.GetNamedBufferSubData(c.count, GLintptr(c.countOffset), sizeof(drawn), &drawn);
        drawn = std::min(drawn, c.maxDrawCount);
        if (drawn == 0)
            return;
        if (c.indexed)
            gl_.MultiDrawElementsIndirect(mode, indexType_, commands, GLsizei(drawn), 0);
        else
            gl_.MultiDrawArraysIndirect(mode, commands, GLsizei(drawn), 0);
    }

    void operator()(const command::Barrier& c) { gl_.MemoryBarrier(c.bits); }

    void operator()(const command::InsertLabel& c)
    {
        gl_.DebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, 0, GL_DEBUG_SEVERITY_NOTIFICATION, -1,
                               c.name.c_str());
    }

    void operator()(const command::Draw& c)
    {
        prepareDraw(c.firstInstance);
        const GLenum mode = pipeline_->state().primitive;
        // The plainest entry point that expresses the draw: drivers validate it fastest.
        if (c.instanceCount == 1 && c.firstInstance == 0)
            gl_.DrawArrays(mode, GLint(c.firstVertex), GLsizei(c.vertexCount));
        else
            gl_.DrawArraysInstancedBaseInstance(mode, GLint(c.firstVertex), GLsizei(c.vertexCount),
                                                GLsizei(c.instanceCount), c.firstInstance);
    }

    void operator()(const command::DrawIndexed& c)
    {
        prepareDraw(c.firstInstance);
        bindIndexBufferToVertexArray();
        const std::uint64_t indexSize = indexType_ == GL_UNSIGNED_SHORT ? 2 : 4;
        const auto* first = reinterpret_cast<const void*>(std::uintptr_t(indexOffset_ + c.firstIndex * indexSize));
        const GLenum mode = pipeline_->state().primitive;
        if (c.instanceCount == 1 && c.firstInstance == 0 && c.vertexOffset == 0)
            gl_.DrawElements(mode, GLsizei(c.indexCount), indexType_, first);
        else if (c.instanceCount == 1 && c.firstInstance == 0)
            gl_.DrawElementsBaseVertex(mode, GLsizei(c.indexCount), indexType_, first, c.vertexOffset);
        else
            gl_.DrawElementsInstancedBaseVertexBaseInstance(mode, GLsizei(c.indexCount), indexType_, first,
                                                            GLsizei(c.instanceCount), c.vertexOffset, c.firstInstance);
    }

    void operator()(const command::CopyBuffer& c)
    {
        gl_.CopyNamedBufferSubData(c.src, c.dst, GLintptr(c.srcOffset), GLintptr(c.dstOffset), GLsizeiptr(c.size));
    }

    void operator()(const command::CopyTexture& c)
    {
        const rhi::TextureDesc& d = c.src->desc();
        const GLint srcZ = c.src->isArray() ? GLint(c.srcLayer) : 0;
        const GLint dstZ = c.dst->isArray() ? GLint(c.dstLayer) : 0;
        for (std::uint32_t level = 0; level < d.mipLevels; ++level)
            gl_.CopyImageSubData(c.src->name(), c.src->target(), GLint(level), 0, 0, srcZ, c.dst->name(),
                                 c.dst->target(), GLint(level), 0, 0, dstZ, GLsizei(rhi::mipExtent(d.width, level)),
                                 GLsizei(rhi::mipExtent(d.height, level)), 1);
    }

    // Synchronous readback into the mapped buffer, so later commands of the list see the bytes.
    void operator()(const command::CopyTextureToBuffer& c)
    {
        const rhi::TextureDesc& d = c.src->desc();
        const GlTextureFormat f = glTextureFormat(d.format);
        scratch_.resize(rhi::levelSize(d, c.level));
        gl_.GetTextureSubImage(c.src->name(), GLint(c.level), 0, 0, c.src->isArray() ? GLint(c.layer) : 0,
                               GLsizei(rhi::mipExtent(d.width, c.level)), GLsizei(rhi::mipExtent(d.height, c.level)), 1,
                               f.pixelFormat, f.pixelType, GLsizei(scratch_.size()), scratch_.data());
        if (d.format == rhi::Format::D24S8)
            moveDepthToLowBits();
        std::memcpy(c.dst->mapped() + c.dstOffset, scratch_.data(), scratch_.size());
    }

    // A blit from a multisampled read framebuffer averages each pixel's samples (GL 4.5 section 18.3.1); it obeys the
    // scissor test, so that goes off first. The attachments are detached after, so no framebuffer keeps a texture.
    void operator()(const command::ResolveTexture& c)
    {
        const auto width = GLint(c.src->desc().width);
        const auto height = GLint(c.src->desc().height);
        gl_.NamedFramebufferTexture(r_.resolveRead, GL_COLOR_ATTACHMENT0, c.src->name(), 0);
        gl_.NamedFramebufferReadBuffer(r_.resolveRead, GL_COLOR_ATTACHMENT0);
        gl_.NamedFramebufferTexture(r_.resolveDraw, GL_COLOR_ATTACHMENT0, c.dst->name(), 0);
        gl_.NamedFramebufferDrawBuffer(r_.resolveDraw, GL_COLOR_ATTACHMENT0);
        cache_.enable(GlStateCache::Cap::ScissorTest, false);
        gl_.BlitNamedFramebuffer(r_.resolveRead, r_.resolveDraw, 0, 0, width, height, 0, 0, width, height,
                                 GL_COLOR_BUFFER_BIT, GL_NEAREST);
        gl_.NamedFramebufferTexture(r_.resolveRead, GL_COLOR_ATTACHMENT0, 0, 0);
        gl_.NamedFramebufferTexture(r_.resolveDraw, GL_COLOR_ATTACHMENT0, 0, 0);
    }

    void operator()(const command::WriteTimestamp& c) { c.queries->write(c.index); }
    void operator()(const command::PushLabel& c)
    {
        gl_.PushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, c.name.c_str());
    }
    void operator()(const command::PopLabel&) { gl_.PopDebugGroup(); }

private:
    void applyWriteMasks(const GlFixedState& s)
    {
        cache_.depthMask(s.depthMask);
        for (GLuint i = 0; i < s.targets.size(); ++i)
            cache_.colorMask(i, s.targets[i].mask);
    }

    void bindIndexBufferToVertexArray()
    {
        GlVertexArrayCache& vao = pipeline_->vertexArrayCache();
        if (vao.indexBuffer != indexBuffer_) {
            vao.indexBuffer = indexBuffer_;
            gl_.VertexArrayElementBuffer(pipeline_->vertexArray(), indexBuffer_);
        }
    }

    void prepareDraw(std::uint32_t firstInstance)
    {
        // A dispatch since bindPipeline made its own program current.
        cache_.useProgram(pipeline_->program());
        GlVertexArrayCache& vao = pipeline_->vertexArrayCache();
        if (vao.generation != r_.generation) {
            vao.generation = r_.generation;
            vao.vertexBuffers.assign(vao.vertexBuffers.size(), {~0u, 0});
            vao.indexBuffer = ~0u;
            vao.baseInstance = -1;
        }
        for (std::uint32_t slot = 0; slot < vao.vertexBuffers.size() && slot < maxVertexBuffers; ++slot) {
            if (vao.vertexBuffers[slot] == vertexBuffers_[slot])
                continue;
            vao.vertexBuffers[slot] = vertexBuffers_[slot];
            gl_.VertexArrayVertexBuffer(pipeline_->vertexArray(), slot, vertexBuffers_[slot].first,
                                        GLintptr(vertexBuffers_[slot].second), pipeline_->stride(slot));
        }
        if (pipeline_->baseInstanceLocation() >= 0 && vao.baseInstance != firstInstance) {
            vao.baseInstance = firstInstance;
            gl_.ProgramUniform1i(pipeline_->program(), pipeline_->baseInstanceLocation(), GLint(firstInstance));
        }
    }

    // GL_UNSIGNED_INT_24_8 holds depth in the high 24 bits; the RHI (like Vulkan) wants the low 24.
    void moveDepthToLowBits()
    {
        for (std::size_t i = 0; i + 4 <= scratch_.size(); i += 4) {
            std::uint32_t word;
            std::memcpy(&word, scratch_.data() + i, 4);
            word >>= 8;
            std::memcpy(scratch_.data() + i, &word, 4);
        }
    }

    const GlReplayContext& r_;
    const GlFunctions& gl_;
    GlStateCache& cache_;
    const GlPipeline* pipeline_ = nullptr;
    GLuint computeProgram_ = 0;
    std::array<std::pair<GLuint, std::uint64_t>, maxVertexBuffers> vertexBuffers_{};
    GLuint indexBuffer_ = 0;
    GLenum indexType_ = GL_UNSIGNED_INT;
    std::uint64_t indexOffset_ = 0;
    std::vector<std::byte> scratch_;
};

} // namespace

void GlCommandList::apiBeginPass(const rhi::PassDesc& pass)
{
    commands_.push_back(command::BeginPass{&glObject<const GlFramebuffer>(*pass.framebuffer, "beginPass framebuffer"),
                                           pass.clearColor, pass.clearDepth});
}

void GlCommandList::apiEndPass() { commands_.push_back(command::EndPass{}); }

void GlCommandList::apiSetViewport(const rhi::Viewport& viewport)
{
    commands_.push_back(command::SetViewport{viewport});
}

void GlCommandList::apiSetScissor(const rhi::Rect& scissor) { commands_.push_back(command::SetScissor{scissor}); }

void GlCommandList::apiSetDepthBias(const rhi::DepthBias& bias)
{
    commands_.push_back(command::SetDepthBias{rhi::signedDepthBias(device_.conventions(), bias)});
}

void GlCommandList::apiBindPipeline(const rhi::Pipeline& pipeline)
{
    commands_.push_back(command::BindPipeline{&glObject<const GlPipeline>(pipeline, "bindPipeline pipeline")});
}

void GlCommandList::apiBindVertexBuffer(std::uint32_t slot, const rhi::Buffer& buffer, std::uint64_t offset)
{
    commands_.push_back(
        command::BindVertexBuffer{slot, glObject<const GlBuffer>(buffer, "vertex buffer").name(), offset});
}

void GlCommandList::apiBindIndexBuffer(const rhi::Buffer& buffer, rhi::IndexType type, std::uint64_t offset)
{
    commands_.push_back(
        command::BindIndexBuffer{glObject<const GlBuffer>(buffer, "index buffer").name(),
                                 GLenum(type == rhi::IndexType::UInt16 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT), offset});
}

void GlCommandList::apiBindUniformBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                                         std::uint64_t size)
{
    commands_.push_back(
        command::BindUniformBuffer{binding, glObject<const GlBuffer>(buffer, "uniform buffer").name(), offset, size});
}

void GlCommandList::apiBindTexture(std::uint32_t binding, const rhi::Texture& texture, const rhi::Sampler& sampler)
{
    commands_.push_back(command::BindTexture{binding, glObject<const GlTexture>(texture, "bound texture").name(),
                                             glObject<const GlSampler>(sampler, "bound sampler").name()});
}

void GlCommandList::apiBindStorageBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                                         std::uint64_t size)
{
    commands_.push_back(
        command::BindStorageBuffer{binding, glObject<const GlBuffer>(buffer, "storage buffer").name(), offset, size});
}

void GlCommandList::apiBindStorageTexture(std::uint32_t binding, const rhi::Texture& texture, std::uint32_t level)
{
    const auto& t = glObject<const GlTexture>(texture, "storage texture");
    commands_.push_back(
        command::BindStorageTexture{binding, t.name(), level, glTextureFormat(t.desc().format).internalFormat});
}

void GlCommandList::apiBindComputePipeline(const rhi::ComputePipeline& pipeline)
{
    commands_.push_back(
        command::BindComputePipeline{glObject<const GlComputePipeline>(pipeline, "compute pipeline").program()});
}

void GlCommandList::apiDispatch(std::uint32_t x, std::uint32_t y, std::uint32_t z)
{
    commands_.push_back(command::Dispatch{x, y, z});
}

void GlCommandList::apiDispatchIndirect(const rhi::Buffer& buffer, std::uint64_t offset)
{
    commands_.push_back(command::DispatchIndirect{glObject<const GlBuffer>(buffer, "indirect buffer").name(), offset});
}

void GlCommandList::apiDrawIndirect(const rhi::Buffer& buffer, std::uint64_t offset)
{
    commands_.push_back(command::DrawIndirect{glObject<const GlBuffer>(buffer, "indirect buffer").name(), offset});
}

void GlCommandList::apiDrawIndexedIndirect(const rhi::Buffer& buffer, std::uint64_t offset)
{
    commands_.push_back(
        command::DrawIndexedIndirect{glObject<const GlBuffer>(buffer, "indirect buffer").name(), offset});
}

void GlCommandList::apiDrawIndirectCount(const rhi::Buffer& buffer, std::uint64_t offset, const rhi::Buffer& count,
                                         std::uint64_t countOffset, std::uint32_t maxDrawCount)
{
    commands_.push_back(command::DrawIndirectCount{glObject<const GlBuffer>(buffer, "indirect buffer").name(), offset,
                                                   glObject<const GlBuffer>(count, "count buffer").name(), countOffset,
                                                   maxDrawCount, false, device_.capabilities().drawIndirectCount});
}

void GlCommandList::apiDrawIndexedIndirectCount(const rhi::Buffer& buffer, std::uint64_t offset,
                                                const rhi::Buffer& count, std::uint64_t countOffset,
                                                std::uint32_t maxDrawCount)
{
    commands_.push_back(command::DrawIndirectCount{glObject<const GlBuffer>(buffer, "indirect buffer").name(), offset,
                                                   glObject<const GlBuffer>(count, "count buffer").name(), countOffset,
                                                   maxDrawCount, true, device_.capabilities().drawIndirectCount});
}

void GlCommandList::apiBarrier(const rhi::Barrier& barrier)
{
    // Only shader stores are incoherent in GL: every other write is ordered before later commands by the API itself
    // (GL 4.5 section 7.12.2, "Shader Memory Access Ordering"). The bits name how the writes are read next.
    const rhi::Access shaderWrites = rhi::Access::StorageBufferWrite | rhi::Access::StorageImageWrite;
    if (!rhi::hasFlag(barrier.src.access, shaderWrites))
        return;
    GLbitfield bits = 0;
    const auto add = [&](rhi::Access access, GLbitfield bit) {
        if (rhi::hasFlag(barrier.dst.access, access))
            bits |= bit;
    };
    add(rhi::Access::IndirectRead, GL_COMMAND_BARRIER_BIT);
    add(rhi::Access::VertexRead, GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    add(rhi::Access::IndexRead, GL_ELEMENT_ARRAY_BARRIER_BIT);
    add(rhi::Access::UniformRead, GL_UNIFORM_BARRIER_BIT);
    add(rhi::Access::SampledRead, GL_TEXTURE_FETCH_BARRIER_BIT);
    add(rhi::Access::StorageBufferRead | rhi::Access::StorageBufferWrite, GL_SHADER_STORAGE_BARRIER_BIT);
    add(rhi::Access::StorageImageRead | rhi::Access::StorageImageWrite, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    add(rhi::Access::AttachmentRead | rhi::Access::AttachmentWrite, GL_FRAMEBUFFER_BARRIER_BIT);
    add(rhi::Access::CopyRead | rhi::Access::CopyWrite,
        GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
    add(rhi::Access::HostRead, GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    if (bits == 0)
        return;
    // Barriers with nothing between them are one barrier with all their bits: one glMemoryBarrier, which a driver may
    // implement as a whole finish (llvmpipe does).
    if (!commands_.empty())
        if (auto* previous = std::get_if<command::Barrier>(&commands_.back())) {
            previous->bits |= bits;
            return;
        }
    commands_.push_back(command::Barrier{bits});
}

void GlCommandList::apiInsertLabel(std::string_view name)
{
    commands_.push_back(command::InsertLabel{std::string(name)});
}

void GlCommandList::apiDraw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
                            std::uint32_t firstInstance)
{
    commands_.push_back(command::Draw{vertexCount, instanceCount, firstVertex, firstInstance});
}

void GlCommandList::apiDrawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                                   std::int32_t vertexOffset, std::uint32_t firstInstance)
{
    commands_.push_back(command::DrawIndexed{indexCount, instanceCount, firstIndex, vertexOffset, firstInstance});
}

void GlCommandList::apiCopyBuffer(const rhi::Buffer& src, std::uint64_t srcOffset, rhi::Buffer& dst,
                                  std::uint64_t dstOffset, std::uint64_t size)
{
    commands_.push_back(command::CopyBuffer{glObject<const GlBuffer>(src, "copy source").name(), srcOffset,
                                            glObject<GlBuffer>(dst, "copy destination").name(), dstOffset, size});
}

void GlCommandList::apiCopyTexture(const rhi::Texture& src, std::uint32_t srcLayer, rhi::Texture& dst,
                                   std::uint32_t dstLayer)
{
    commands_.push_back(command::CopyTexture{&glObject<const GlTexture>(src, "copy source"), srcLayer,
                                             &glObject<GlTexture>(dst, "copy destination"), dstLayer});
}

void GlCommandList::apiCopyTextureToBuffer(const rhi::Texture& src, std::uint32_t layer, std::uint32_t level,
                                           rhi::Buffer& dst, std::uint64_t dstOffset)
{
    commands_.push_back(command::CopyTextureToBuffer{&glObject<const GlTexture>(src, "copy source"), layer, level,
                                                     &glObject<GlBuffer>(dst, "copy destination"), dstOffset});
}

void GlCommandList::apiResolveTexture(const rhi::Texture& src, rhi::Texture& dst)
{
    commands_.push_back(command::ResolveTexture{&glObject<const GlTexture>(src, "resolve source"),
                                                &glObject<GlTexture>(dst, "resolve destination")});
}

void GlCommandList::apiWriteTimestamp(rhi::TimestampQueries& queries, std::uint32_t index)
{
    commands_.push_back(command::WriteTimestamp{&glObject<GlTimestampQueries>(queries, "timestamp queries"), index});
}

void GlCommandList::apiPushLabel(std::string_view name) { commands_.push_back(command::PushLabel{std::string(name)}); }

void GlCommandList::apiPopLabel() { commands_.push_back(command::PopLabel{}); }

void GlCommandList::replay(const GlReplayContext& context)
{
    // Emptied even when a command throws; clear() keeps the capacity for the next frame.
    struct ClearOnExit {
        std::vector<command::Any>& commands;
        ~ClearOnExit() { commands.clear(); }
    } clearOnExit{commands_};
    Replayer replayer(context);
    for (const command::Any& c : commands_)
        std::visit(replayer, c);
}

} // namespace penumbra::opengl
