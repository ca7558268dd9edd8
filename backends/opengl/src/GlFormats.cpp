#include "GlFormats.hpp"

namespace penumbra::opengl {

GlTextureFormat glTextureFormat(rhi::Format format)
{
    switch (format) {
    case rhi::Format::RGBA8:
        return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_NONE};
    case rhi::Format::RGBA16F:
        return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, GL_NONE};
    case rhi::Format::RGBA32F:
        return {GL_RGBA32F, GL_RGBA, GL_FLOAT, GL_NONE};
    case rhi::Format::D16:
        return {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, GL_DEPTH_ATTACHMENT};
    // Depth sits in the high 24 bits of GL's packed word; the RHI's layout has it in the low 24.
    case rhi::Format::D24S8:
        return {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, GL_DEPTH_STENCIL_ATTACHMENT};
    case rhi::Format::D32F:
        return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, GL_DEPTH_ATTACHMENT};
    case rhi::Format::RGBA8_SRGB:
        return {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, GL_NONE};
    case rhi::Format::R8:
        return {GL_R8, GL_RED, GL_UNSIGNED_BYTE, GL_NONE};
    case rhi::Format::RG8:
        return {GL_RG8, GL_RG, GL_UNSIGNED_BYTE, GL_NONE};
    case rhi::Format::R16F:
        return {GL_R16F, GL_RED, GL_HALF_FLOAT, GL_NONE};
    case rhi::Format::RG16F:
        return {GL_RG16F, GL_RG, GL_HALF_FLOAT, GL_NONE};
    case rhi::Format::R32F:
        return {GL_R32F, GL_RED, GL_FLOAT, GL_NONE};
    }
    return {GL_NONE, GL_NONE, GL_NONE, GL_NONE};
}

GlVertexFormat glVertexFormat(rhi::VertexFormat format)
{
    switch (format) {
    case rhi::VertexFormat::Float:
        return {1, GL_FLOAT, GL_FALSE};
    case rhi::VertexFormat::Float2:
        return {2, GL_FLOAT, GL_FALSE};
    case rhi::VertexFormat::Float3:
        return {3, GL_FLOAT, GL_FALSE};
    case rhi::VertexFormat::Float4:
        return {4, GL_FLOAT, GL_FALSE};
    case rhi::VertexFormat::UByte4Norm:
        return {4, GL_UNSIGNED_BYTE, GL_TRUE};
    }
    return {4, GL_FLOAT, GL_FALSE};
}

GLenum glCompareFunc(rhi::CompareOp op)
{
    switch (op) {
    case rhi::CompareOp::Never:
        return GL_NEVER;
    case rhi::CompareOp::Less:
        return GL_LESS;
    case rhi::CompareOp::LessOrEqual:
        return GL_LEQUAL;
    case rhi::CompareOp::Equal:
        return GL_EQUAL;
    case rhi::CompareOp::Greater:
        return GL_GREATER;
    case rhi::CompareOp::GreaterOrEqual:
        return GL_GEQUAL;
    case rhi::CompareOp::NotEqual:
        return GL_NOTEQUAL;
    case rhi::CompareOp::Always:
        return GL_ALWAYS;
    }
    return GL_ALWAYS;
}

GLenum glBlendFactor(rhi::BlendFactor factor)
{
    switch (factor) {
    case rhi::BlendFactor::Zero:
        return GL_ZERO;
    case rhi::BlendFactor::One:
        return GL_ONE;
    case rhi::BlendFactor::SrcColor:
        return GL_SRC_COLOR;
    case rhi::BlendFactor::OneMinusSrcColor:
        return GL_ONE_MINUS_SRC_COLOR;
    case rhi::BlendFactor::SrcAlpha:
        return GL_SRC_ALPHA;
    case rhi::BlendFactor::OneMinusSrcAlpha:
        return GL_ONE_MINUS_SRC_ALPHA;
    case rhi::BlendFactor::DstColor:
        return GL_DST_COLOR;
    case rhi::BlendFactor::OneMinusDstColor:
        return GL_ONE_MINUS_DST_COLOR;
    case rhi::BlendFactor::DstAlpha:
        return GL_DST_ALPHA;
    case rhi::BlendFactor::OneMinusDstAlpha:
        return GL_ONE_MINUS_DST_ALPHA;
    }
    return GL_ONE;
}

GLenum glBlendEquation(rhi::BlendOp op)
{
    switch (op) {
    case rhi::BlendOp::Add:
        return GL_FUNC_ADD;
    case rhi::BlendOp::Subtract:
        return GL_FUNC_SUBTRACT;
    case rhi::BlendOp::ReverseSubtract:
        return GL_FUNC_REVERSE_SUBTRACT;
    case rhi::BlendOp::Min:
        return GL_MIN;
    case rhi::BlendOp::Max:
        return GL_MAX;
    }
    return GL_FUNC_ADD;
}

GLenum glFilter(rhi::Filter filter) { return filter == rhi::Filter::Linear ? GL_LINEAR : GL_NEAREST; }

GLenum glMinFilter(rhi::Filter filter, rhi::MipFilter mip)
{
    const bool linear = filter == rhi::Filter::Linear;
    switch (mip) {
    case rhi::MipFilter::None:
        return linear ? GL_LINEAR : GL_NEAREST;
    case rhi::MipFilter::Nearest:
        return linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
    case rhi::MipFilter::Linear:
        return linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
    }
    return GL_NEAREST;
}

GLenum glWrap(rhi::AddressMode mode)
{
    switch (mode) {
    case rhi::AddressMode::ClampToEdge:
        return GL_CLAMP_TO_EDGE;
    case rhi::AddressMode::Repeat:
        return GL_REPEAT;
    case rhi::AddressMode::MirroredRepeat:
        return GL_MIRRORED_REPEAT;
    }
    return GL_CLAMP_TO_EDGE;
}

GLenum glPrimitive(rhi::PrimitiveTopology topology)
{
    switch (topology) {
    case rhi::PrimitiveTopology::TriangleList:
        return GL_TRIANGLES;
    case rhi::PrimitiveTopology::TriangleStrip:
        return GL_TRIANGLE_STRIP;
    case rhi::PrimitiveTopology::LineList:
        return GL_LINES;
    case rhi::PrimitiveTopology::PointList:
        return GL_POINTS;
    }
    return GL_TRIANGLES;
}

} // namespace penumbra::opengl
