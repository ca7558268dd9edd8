#pragma once

#include "penumbra/opengl/GlFunctions.hpp"
#include "penumbra/rhi/Pipeline.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace penumbra::opengl {

// Mirrors the GL state the backend sets, so that identical consecutive settings cost nothing.
// invalidate() forgets everything (each submit starts with it: raw GL may have run in between).
class GlStateCache {
public:
    enum class Cap : std::uint8_t { DepthTest, DepthClamp, CullFace, ScissorTest, Count };

    GlStateCache(const GlFunctions& gl, std::uint32_t uniformBindings, std::uint32_t textureUnits);
    void invalidate();

    void enable(Cap cap, bool on);
    void depthFunc(GLenum func);
    void depthMask(GLboolean write);
    void cullFace(GLenum face);
    void frontFace(GLenum mode);
    void polygonOffset(const rhi::DepthBias& bias);
    void blend(GLuint target, bool enable, GLenum srcColor, GLenum dstColor, GLenum colorEquation, GLenum srcAlpha,
               GLenum dstAlpha, GLenum alphaEquation);
    void colorMask(GLuint target, const std::array<GLboolean, 4>& mask);

    void useProgram(GLuint program);
    void bindVertexArray(GLuint vertexArray);
    void bindDrawFramebuffer(GLuint framebuffer);
    void viewport(const std::array<float, 4>& rect);
    void scissor(const std::array<GLint, 4>& rect);
    void uniformBuffer(GLuint binding, GLuint buffer, GLintptr offset, GLsizeiptr size);
    void texture(GLuint unit, GLuint texture, GLuint sampler);

private:
    static constexpr std::uint32_t maxTargets = 8;
    struct BlendSetting {
        std::int8_t enabled = -1;
        std::array<GLenum, 6> funcs{};
        bool funcsKnown = false;
    };
    struct UniformRange {
        GLuint buffer = 0;
        GLintptr offset = -1;
        GLsizeiptr size = 0;
    };

    const GlFunctions& gl_;
    std::array<std::int8_t, std::size_t(Cap::Count)> caps_{};
    GLenum depthFunc_ = 0;
    std::int16_t depthMask_ = -1;
    GLenum cullFace_ = 0;
    GLenum frontFace_ = 0;
    bool biasKnown_ = false;
    rhi::DepthBias bias_;
    std::array<BlendSetting, maxTargets> blend_{};
    std::array<std::array<GLboolean, 4>, maxTargets> colorMask_{};
    std::array<bool, maxTargets> colorMaskKnown_{};
    GLuint program_ = ~0u;
    GLuint vertexArray_ = ~0u;
    GLuint framebuffer_ = ~0u;
    std::array<float, 4> viewport_{};
    bool viewportKnown_ = false;
    std::array<GLint, 4> scissor_{};
    bool scissorKnown_ = false;
    std::vector<UniformRange> uniformBuffers_;
    std::vector<std::pair<GLuint, GLuint>> textures_; // texture, sampler per unit
};

} // namespace penumbra::opengl
