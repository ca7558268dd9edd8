#pragma once

#include "GlContext.hpp"
#include "GlHandle.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Resources.hpp"

#include <memory>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

namespace penumbra::opengl {

using GlContextPtr = std::shared_ptr<const GlContext>;

// The GL object behind an RHI interface; throws when it belongs to another backend.
// GlType is final, so comparing exact types suffices, and it costs far less than dynamic_cast per draw.
template <typename GlType, typename RhiType>
GlType& glObject(RhiType& object, const char* what)
{
    static_assert(std::is_final_v<std::remove_const_t<GlType>>);
    if (typeid(object) != typeid(GlType))
        throw rhi::Error(std::string(what) + " was not created by an OpenGL device");
    return static_cast<GlType&>(object);
}

// Persistently mapped and coherent: write/read are memcpy, and a finished submit means the GPU is done.
class GlBuffer final : public rhi::Buffer {
public:
    GlBuffer(GlContextPtr context, const rhi::BufferDesc& desc);
    ~GlBuffer() override; // unmaps; name_ then deletes the buffer

    const rhi::BufferDesc& desc() const override { return desc_; }
    void write(std::uint64_t offset, std::span<const std::byte> data) override;
    void read(std::uint64_t offset, std::span<std::byte> data) const override;

    GLuint name() const { return name_.get(); }
    std::byte* mapped() const { return mapped_; }

private:
    GlContextPtr context_;
    rhi::BufferDesc desc_;
    GlBufferName name_;
    std::byte* mapped_ = nullptr;
};

class GlTexture final : public rhi::Texture {
public:
    GlTexture(GlContextPtr context, const rhi::TextureDesc& desc);

    const rhi::TextureDesc& desc() const override { return desc_; }
    GLuint name() const { return name_.get(); }
    GLenum target() const { return target_; }
    // Layered targets (2D array, cube-map array) take the RHI layer as GL's layer or z offset;
    // for a cube-map array GL's layer-face is 6 * cube + face, the RHI's layer exactly.
    bool isArray() const { return target_ == GL_TEXTURE_2D_ARRAY || target_ == GL_TEXTURE_CUBE_MAP_ARRAY; }

private:
    GlContextPtr context_;
    rhi::TextureDesc desc_;
    GLenum target_ = GL_TEXTURE_2D;
    GlTextureName name_;
};

class GlSampler final : public rhi::Sampler {
public:
    GlSampler(GlContextPtr context, const rhi::SamplerDesc& desc, const rhi::Conventions& conventions);

    const rhi::SamplerDesc& desc() const override { return desc_; }
    GLuint name() const { return name_.get(); }

private:
    GlContextPtr context_;
    rhi::SamplerDesc desc_;
    GlSamplerName name_;
};

class GlFramebuffer final : public rhi::Framebuffer {
public:
    GlFramebuffer(GlContextPtr context, const rhi::FramebufferDesc& desc);

    std::uint32_t width() const override { return width_; }
    std::uint32_t height() const override { return height_; }
    const rhi::AttachmentFormats& formats() const override { return formats_; }
    GLuint name() const { return name_.get(); }
    std::uint32_t colorCount() const { return colorCount_; }
    bool hasDepth() const { return hasDepth_; }

private:
    GlContextPtr context_;
    GlFramebufferName name_;
    rhi::AttachmentFormats formats_;
    std::uint32_t width_ = 0;
    std::uint32_t height_ = 0;
    std::uint32_t colorCount_ = 0;
    bool hasDepth_ = false;
};

class GlTimestampQueries final : public rhi::TimestampQueries {
public:
    GlTimestampQueries(GlContextPtr context, std::uint32_t count);

    std::uint32_t count() const override { return std::uint32_t(names_.size()); }
    void write(std::uint32_t index);
    // Nanoseconds; waits for the results.
    std::vector<double> read() const;

private:
    GlContextPtr context_;
    std::vector<GlQueryName> names_;
    std::vector<bool> written_; // reading a query never written is a GL error
};

} // namespace penumbra::opengl
