#include "GlResources.hpp"

#include "GlFormats.hpp"
#include "penumbra/rhi/BackendSupport.hpp"

#include <cstring>
#include <fmt/format.h>

namespace penumbra::opengl {
namespace {

void label(const GlFunctions& gl, GLenum identifier, GLuint name, const std::string& debugName)
{
    if (!debugName.empty())
        gl.ObjectLabel(identifier, name, GLsizei(debugName.size()), debugName.c_str());
}

void attach(const GlFunctions& gl, GLuint framebuffer, GLenum attachment, const rhi::Attachment& a)
{
    const auto& texture = glObject<const GlTexture>(*a.texture, "framebuffer attachment");
    if (texture.isArray())
        gl.NamedFramebufferTextureLayer(framebuffer, attachment, texture.name(), 0, GLint(a.layer));
    else
        gl.NamedFramebufferTexture(framebuffer, attachment, texture.name(), 0);
}

GLenum textureTarget(const rhi::TextureDesc& desc)
{
    if (desc.cube)
        return GL_TEXTURE_CUBE_MAP_ARRAY;
    return desc.array || desc.layers > 1 ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D;
}

} // namespace

GlBuffer::GlBuffer(GlContextPtr context, const rhi::BufferDesc& desc) : context_(std::move(context)), desc_(desc)
{
    if (desc.size == 0)
        throw rhi::Error(fmt::format("buffer '{}': size must not be 0", desc.debugName));
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    constexpr GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    name_ = createName<GlBufferName>(*context_, gl.CreateBuffers);
    gl.NamedBufferStorage(name_.get(), GLsizeiptr(desc.size), nullptr, flags);
    mapped_ = static_cast<std::byte*>(gl.MapNamedBufferRange(name_.get(), 0, GLsizeiptr(desc.size), flags));
    if (!mapped_)
        throw rhi::Error(fmt::format("buffer '{}': cannot map {} bytes persistently", desc.debugName, desc.size));
    label(gl, GL_BUFFER, name_.get(), desc.debugName);
}

GlBuffer::~GlBuffer()
{
    context_->makeCurrent();
    context_->gl().UnmapNamedBuffer(name_.get());
}

void GlBuffer::checkRange(const char* operation, std::uint64_t offset, std::uint64_t size) const
{
    if (offset > desc_.size || size > desc_.size - offset)
        throw rhi::Error(fmt::format("buffer '{}': {} of {} bytes at offset {} exceeds its size {}", desc_.debugName,
                                     operation, size, offset, desc_.size));
}

void GlBuffer::write(std::uint64_t offset, std::span<const std::byte> data)
{
    checkRange("write", offset, data.size());
    std::memcpy(mapped_ + offset, data.data(), data.size());
}

void GlBuffer::read(std::uint64_t offset, std::span<std::byte> data) const
{
    checkRange("read", offset, data.size());
    std::memcpy(data.data(), mapped_ + offset, data.size());
}

GlTexture::GlTexture(GlContextPtr context, const rhi::TextureDesc& desc) : context_(std::move(context)), desc_(desc)
{
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    const GlTextureFormat format = glTextureFormat(desc.format);
    target_ = textureTarget(desc);
    GLuint texture = 0;
    gl.CreateTextures(target_, 1, &texture);
    name_ = GlTextureName(*context_, texture);
    if (isArray())
        gl.TextureStorage3D(name_.get(), 1, format.internalFormat, GLsizei(desc.width), GLsizei(desc.height),
                            GLsizei(desc.layers));
    else
        gl.TextureStorage2D(name_.get(), 1, format.internalFormat, GLsizei(desc.width), GLsizei(desc.height));
    gl.TextureParameteri(name_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TextureParameteri(name_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (desc.format == rhi::Format::D24S8)
        gl.TextureParameteri(name_.get(), GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT); // sample depth, not stencil
    label(gl, GL_TEXTURE, name_.get(), desc.debugName);
}

GlSampler::GlSampler(GlContextPtr context, const rhi::SamplerDesc& desc, const rhi::Conventions& conventions)
    : context_(std::move(context)), desc_(desc)
{
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    name_ = createName<GlSamplerName>(*context_, gl.CreateSamplers);
    const GLint filter = desc.filter == rhi::Filter::Linear ? GL_LINEAR : GL_NEAREST;
    const GLint wrap = desc.address == rhi::AddressMode::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    gl.SamplerParameteri(name_.get(), GL_TEXTURE_MIN_FILTER, filter);
    gl.SamplerParameteri(name_.get(), GL_TEXTURE_MAG_FILTER, filter);
    gl.SamplerParameteri(name_.get(), GL_TEXTURE_WRAP_S, wrap);
    gl.SamplerParameteri(name_.get(), GL_TEXTURE_WRAP_T, wrap);
    gl.SamplerParameteri(name_.get(), GL_TEXTURE_WRAP_R, wrap);
    if (desc.compare) {
        gl.SamplerParameteri(name_.get(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        gl.SamplerParameteri(name_.get(), GL_TEXTURE_COMPARE_FUNC, GLint(glCompareFunc(conventions.shadowCompareOp())));
    }
    label(gl, GL_SAMPLER, name_.get(), desc.debugName);
}

GlFramebuffer::GlFramebuffer(GlContextPtr context, const rhi::FramebufferDesc& desc) : context_(std::move(context))
{
    rhi::checkFramebuffer(desc);
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    name_ = createName<GlFramebufferName>(*context_, gl.CreateFramebuffers);
    const rhi::Texture* any = desc.depth.texture;
    std::vector<GLenum> drawBuffers;
    for (const rhi::Attachment& color : desc.colors) {
        const GLenum point = GL_COLOR_ATTACHMENT0 + GLenum(drawBuffers.size());
        attach(gl, name_.get(), point, color);
        drawBuffers.push_back(point);
        any = color.texture;
    }
    if (desc.depth.texture) {
        attach(gl, name_.get(), glTextureFormat(desc.depth.texture->desc().format).attachment, desc.depth);
        hasDepth_ = true;
    }
    if (drawBuffers.empty()) {
        gl.NamedFramebufferDrawBuffer(name_.get(), GL_NONE);
        gl.NamedFramebufferReadBuffer(name_.get(), GL_NONE);
    } else {
        gl.NamedFramebufferDrawBuffers(name_.get(), GLsizei(drawBuffers.size()), drawBuffers.data());
    }
    colorCount_ = std::uint32_t(drawBuffers.size());
    width_ = any->desc().width;
    height_ = any->desc().height;
    const GLenum status = gl.CheckNamedFramebufferStatus(name_.get(), GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw rhi::Error(fmt::format("framebuffer '{}' is incomplete (GL status 0x{:x})", desc.debugName, status));
    label(gl, GL_FRAMEBUFFER, name_.get(), desc.debugName);
}

GlTimestampQueries::GlTimestampQueries(GlContextPtr context, std::uint32_t count)
    : context_(std::move(context)), written_(count, false)
{
    if (count == 0)
        throw rhi::Error("timestamp queries: count must not be 0");
    context_->makeCurrent();
    for (std::uint32_t i = 0; i < count; ++i) {
        GLuint query = 0;
        context_->gl().CreateQueries(GL_TIMESTAMP, 1, &query);
        names_.emplace_back(*context_, query);
    }
}

void GlTimestampQueries::write(std::uint32_t index)
{
    context_->gl().QueryCounter(names_[index].get(), GL_TIMESTAMP);
    written_[index] = true;
}

std::vector<double> GlTimestampQueries::read() const
{
    context_->makeCurrent();
    std::vector<double> nanoseconds(names_.size());
    for (std::size_t i = 0; i < names_.size(); ++i) {
        if (!written_[i])
            throw rhi::Error(fmt::format("timestamp query {} was never written by a submitted command list", i));
        GLuint64 value = 0;
        context_->gl().GetQueryObjectui64v(names_[i].get(), GL_QUERY_RESULT, &value);
        nanoseconds[i] = double(value);
    }
    return nanoseconds;
}

} // namespace penumbra::opengl
