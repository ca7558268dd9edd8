#include "GlResources.hpp"

#include "GlFormats.hpp"
#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/MemorySize.hpp"
#include "penumbra/rhi/ValidationRules.hpp"

#include <algorithm>

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

GLenum textureTargetOf(const rhi::TextureDesc& desc)
{
    if (desc.samples > 1)
        return GL_TEXTURE_2D_MULTISAMPLE;
    if (desc.cube)
        return GL_TEXTURE_CUBE_MAP_ARRAY;
    return desc.array || desc.layers > 1 ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D;
}

} // namespace

GlBuffer::GlBuffer(GlContextPtr context, const rhi::BufferDesc& desc) : context_(std::move(context)), desc_(desc)
{
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    constexpr GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    name_ = createName<GlBufferName>(*context_, gl.CreateBuffers);
    // An empty RHI buffer is valid; glNamedBufferStorage refuses size 0 (GL 4.5 section 6.2), so it gets a byte.
    const auto size = GLsizeiptr(std::max<std::uint64_t>(desc.size, 1));
    gl.NamedBufferStorage(name_.get(), size, nullptr, flags);
    mapped_ = static_cast<std::byte*>(gl.MapNamedBufferRange(name_.get(), 0, size, flags));
    if (!mapped_)
        throw rhi::Error(fmt::format("buffer '{}': cannot map {} bytes persistently", desc.debugName, desc.size));
    label(gl, GL_BUFFER, name_.get(), desc.debugName);
}

GlBuffer::~GlBuffer()
{
    context_->makeCurrent();
    context_->gl().UnmapNamedBuffer(name_.get());
}

void GlBuffer::write(std::uint64_t offset, std::span<const std::byte> data)
{
    rhi::writeMappedBuffer(desc_, mapped_, offset, data);
}

void GlBuffer::read(std::uint64_t offset, std::span<std::byte> data) const
{
    rhi::readMappedBuffer(desc_, mapped_, offset, data);
}

GlTexture::GlTexture(GlContextPtr context, const rhi::TextureDesc& desc) : context_(std::move(context)), desc_(desc)
{
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    const GlTextureFormat format = glTextureFormat(desc.format);
    target_ = textureTargetOf(desc);
    GLuint texture = 0;
    gl.CreateTextures(target_, 1, &texture);
    name_ = GlTextureName(*context_, texture);
    const auto levels = GLsizei(desc.mipLevels);
    if (target_ == GL_TEXTURE_2D_MULTISAMPLE) {
        // Fixed sample locations: the same pattern in every pixel, as Vulkan's standard locations are.
        gl.TextureStorage2DMultisample(name_.get(), GLsizei(desc.samples), format.internalFormat, GLsizei(desc.width),
                                       GLsizei(desc.height), GL_TRUE);
        label(gl, GL_TEXTURE, name_.get(), desc.debugName);
        return; // a multisampled texture has no sampler state (GL 4.5 section 8.10, INVALID_ENUM)
    }
    if (isArray())
        gl.TextureStorage3D(name_.get(), levels, format.internalFormat, GLsizei(desc.width), GLsizei(desc.height),
                            GLsizei(desc.layers));
    else
        gl.TextureStorage2D(name_.get(), levels, format.internalFormat, GLsizei(desc.width), GLsizei(desc.height));
    // GL 4.5 section 2.3.1: a command that runs out of memory sets GL_OUT_OF_MEMORY and leaves the state
    // undefined only for that object, which is deleted here with the name.
    if (gl.GetError() == GL_OUT_OF_MEMORY)
        throw rhi::Error(fmt::format("glTextureStorage for {}: GL_OUT_OF_MEMORY", rhi::describeAllocation(desc)));
    gl.TextureParameteri(name_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TextureParameteri(name_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (desc.format == rhi::Format::D24S8)
        gl.TextureParameteri(name_.get(), GL_DEPTH_STENCIL_TEXTURE_MODE,
                             GL_DEPTH_COMPONENT); // sample depth, not stencil
    label(gl, GL_TEXTURE, name_.get(), desc.debugName);
}

GlSampler::GlSampler(GlContextPtr context, const rhi::SamplerDesc& desc, const rhi::Conventions& conventions)
    : context_(std::move(context)), desc_(desc)
{
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    name_ = createName<GlSamplerName>(*context_, gl.CreateSamplers);
    const GLuint sampler = name_.get();
    const rhi::LodRange lod = rhi::samplerLodRange(desc);
    gl.SamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GLint(glMinFilter(desc.minFilter, desc.mipFilter)));
    gl.SamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GLint(glFilter(desc.magFilter)));
    gl.SamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GLint(glWrap(desc.addressU)));
    gl.SamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GLint(glWrap(desc.addressV)));
    gl.SamplerParameteri(sampler, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    gl.SamplerParameterf(sampler, GL_TEXTURE_MIN_LOD, lod.min);
    gl.SamplerParameterf(sampler, GL_TEXTURE_MAX_LOD, lod.max);
    // Only set where asked for: a driver without the extension (maxSamplerAnisotropy 1) rejects the name.
    if (desc.maxAnisotropy > 1.0f)
        gl.SamplerParameterf(sampler, GL_TEXTURE_MAX_ANISOTROPY, desc.maxAnisotropy);
    if (desc.compare) {
        gl.SamplerParameteri(name_.get(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        gl.SamplerParameteri(name_.get(), GL_TEXTURE_COMPARE_FUNC, GLint(glCompareFunc(conventions.shadowCompareOp())));
    }
    label(gl, GL_SAMPLER, name_.get(), desc.debugName);
}

GlFramebuffer::GlFramebuffer(GlContextPtr context, const rhi::FramebufferDesc& desc)
    : context_(std::move(context)), formats_(rhi::attachmentFormats(desc))
{
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
            throw rhi::Error(fmt::format("readTimestamps: query {} was not written by a submitted command list", i));
        GLuint64 value = 0;
        context_->gl().GetQueryObjectui64v(names_[i].get(), GL_QUERY_RESULT, &value);
        nanoseconds[i] = double(value);
    }
    return nanoseconds;
}

} // namespace penumbra::opengl
