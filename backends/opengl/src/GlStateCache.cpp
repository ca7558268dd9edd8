#include "GlStateCache.hpp"

namespace penumbra::opengl {
namespace {

constexpr GLenum capEnum(GlStateCache::Cap cap)
{
    switch (cap) {
    case GlStateCache::Cap::DepthTest:
        return GL_DEPTH_TEST;
    case GlStateCache::Cap::DepthClamp:
        return GL_DEPTH_CLAMP;
    case GlStateCache::Cap::CullFace:
        return GL_CULL_FACE;
    case GlStateCache::Cap::ScissorTest:
        return GL_SCISSOR_TEST;
    case GlStateCache::Cap::Count:
        break;
    }
    return GL_NONE;
}

constexpr GLuint unknownName = ~0u;

} // namespace

GlStateCache::GlStateCache(const GlFunctions& gl, std::uint32_t uniformBindings, std::uint32_t textureUnits)
    : gl_(gl), uniformBuffers_(uniformBindings), textures_(textureUnits)
{
    invalidate();
}

void GlStateCache::invalidate()
{
    caps_.fill(-1);
    depthFunc_ = 0;
    depthMask_ = -1;
    cullFace_ = 0;
    frontFace_ = 0;
    biasKnown_ = false;
    blend_.fill({});
    colorMaskKnown_.fill(false);
    program_ = vertexArray_ = framebuffer_ = unknownName;
    viewportKnown_ = scissorKnown_ = false;
    uniformBuffers_.assign(uniformBuffers_.size(), {});
    textures_.assign(textures_.size(), {unknownName, unknownName});
}

void GlStateCache::enable(Cap cap, bool on)
{
    std::int8_t& known = caps_[std::size_t(cap)];
    if (known == std::int8_t(on))
        return;
    known = std::int8_t(on);
    on ? gl_.Enable(capEnum(cap)) : gl_.Disable(capEnum(cap));
}

void GlStateCache::depthFunc(GLenum func)
{
    if (depthFunc_ != func)
        gl_.DepthFunc(depthFunc_ = func);
}

void GlStateCache::depthMask(GLboolean write)
{
    if (depthMask_ != write) {
        depthMask_ = write;
        gl_.DepthMask(write);
    }
}

void GlStateCache::cullFace(GLenum face)
{
    if (cullFace_ != face)
        gl_.CullFace(cullFace_ = face);
}

void GlStateCache::frontFace(GLenum mode)
{
    if (frontFace_ != mode)
        gl_.FrontFace(frontFace_ = mode);
}

void GlStateCache::polygonOffset(const rhi::DepthBias& bias)
{
    if (biasKnown_ && bias_.constant == bias.constant && bias_.slope == bias.slope && bias_.clamp == bias.clamp)
        return;
    biasKnown_ = true;
    bias_ = bias;
    if (gl_.PolygonOffsetClamp)
        gl_.PolygonOffsetClamp(bias.slope, bias.constant, bias.clamp);
    else
        gl_.PolygonOffset(bias.slope, bias.constant);
}

void GlStateCache::blend(GLuint target, bool enable, GLenum srcColor, GLenum dstColor, GLenum colorEquation,
                         GLenum srcAlpha, GLenum dstAlpha, GLenum alphaEquation)
{
    BlendSetting& s = blend_[target];
    if (s.enabled != std::int8_t(enable)) {
        s.enabled = std::int8_t(enable);
        enable ? gl_.Enablei(GL_BLEND, target) : gl_.Disablei(GL_BLEND, target);
    }
    if (!enable)
        return;
    const std::array<GLenum, 6> funcs{srcColor, dstColor, colorEquation, srcAlpha, dstAlpha, alphaEquation};
    if (s.funcsKnown && s.funcs == funcs)
        return;
    s.funcsKnown = true;
    s.funcs = funcs;
    gl_.BlendFuncSeparatei(target, srcColor, dstColor, srcAlpha, dstAlpha);
    gl_.BlendEquationSeparatei(target, colorEquation, alphaEquation);
}

void GlStateCache::colorMask(GLuint target, const std::array<GLboolean, 4>& mask)
{
    if (colorMaskKnown_[target] && colorMask_[target] == mask)
        return;
    colorMaskKnown_[target] = true;
    colorMask_[target] = mask;
    gl_.ColorMaski(target, mask[0], mask[1], mask[2], mask[3]);
}

void GlStateCache::useProgram(GLuint program)
{
    if (program_ != program)
        gl_.UseProgram(program_ = program);
}

void GlStateCache::bindVertexArray(GLuint vertexArray)
{
    if (vertexArray_ != vertexArray)
        gl_.BindVertexArray(vertexArray_ = vertexArray);
}

void GlStateCache::bindDrawFramebuffer(GLuint framebuffer)
{
    if (framebuffer_ != framebuffer)
        gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_ = framebuffer);
}

void GlStateCache::viewport(const std::array<float, 4>& rect)
{
    if (viewportKnown_ && viewport_ == rect)
        return;
    viewportKnown_ = true;
    viewport_ = rect;
    gl_.ViewportIndexedf(0, rect[0], rect[1], rect[2], rect[3]);
}

void GlStateCache::scissor(const std::array<GLint, 4>& rect)
{
    if (scissorKnown_ && scissor_ == rect)
        return;
    scissorKnown_ = true;
    scissor_ = rect;
    gl_.Scissor(rect[0], rect[1], rect[2], rect[3]);
}

void GlStateCache::uniformBuffer(GLuint binding, GLuint buffer, GLintptr offset, GLsizeiptr size)
{
    if (binding < uniformBuffers_.size()) {
        UniformRange& r = uniformBuffers_[binding];
        if (r.buffer == buffer && r.offset == offset && r.size == size)
            return;
        r = {buffer, offset, size};
    }
    gl_.BindBufferRange(GL_UNIFORM_BUFFER, binding, buffer, offset, size);
}

void GlStateCache::texture(GLuint unit, GLuint texture, GLuint sampler)
{
    if (unit >= textures_.size()) {
        gl_.BindTextureUnit(unit, texture);
        gl_.BindSampler(unit, sampler);
        return;
    }
    auto& [boundTexture, boundSampler] = textures_[unit];
    if (boundTexture != texture)
        gl_.BindTextureUnit(unit, boundTexture = texture);
    if (boundSampler != sampler)
        gl_.BindSampler(unit, boundSampler = sampler);
}

} // namespace penumbra::opengl
