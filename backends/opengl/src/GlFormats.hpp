#pragma once

#include "penumbra/opengl/GlFunctions.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Format.hpp"
#include "penumbra/rhi/Pipeline.hpp"
#include "penumbra/rhi/Resources.hpp"

namespace penumbra::opengl {

// How a format is stored and how its bytes travel to and from the CPU.
struct GlTextureFormat {
    GLenum internalFormat;
    GLenum pixelFormat; // for uploads and readbacks
    GLenum pixelType;
    GLenum attachment; // framebuffer attachment point for depth formats; GL_NONE for colour
};

GlTextureFormat glTextureFormat(rhi::Format format);

struct GlVertexFormat {
    GLint size;
    GLenum type;
    GLboolean normalized;
};

GlVertexFormat glVertexFormat(rhi::VertexFormat format);
GLenum glCompareFunc(rhi::CompareOp op);
GLenum glBlendFactor(rhi::BlendFactor factor);
GLenum glBlendEquation(rhi::BlendOp op);
GLenum glPrimitive(rhi::PrimitiveTopology topology);
GLenum glFilter(rhi::Filter filter);
// GL folds the mip filter into the minification filter (GL 4.5 section 8.14).
GLenum glMinFilter(rhi::Filter filter, rhi::MipFilter mip);
GLenum glWrap(rhi::AddressMode mode);

} // namespace penumbra::opengl
