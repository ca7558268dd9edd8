#pragma once

#include "GlResources.hpp"
#include "penumbra/rhi/Pipeline.hpp"
#include "penumbra/rhi/Shader.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace penumbra::opengl {

class GlOrientation;
class GlProgramCache;

// SPIR-V from glslang, cross-compiled by SPIRV-Cross to GLSL 450 core and compiled by the driver.
class GlShader final : public rhi::Shader {
public:
    GlShader(GlContextPtr context, rhi::CompiledShader compiled, const GlOrientation& orientation);

    const rhi::CompiledShader& compiled() const override { return compiled_; }
    GLuint name() const { return name_.get(); }
    // The GLSL the driver compiled (what a program binary is keyed by).
    const std::string& glsl() const { return glsl_; }

private:
    GlContextPtr context_;
    rhi::CompiledShader compiled_;
    std::string glsl_; // quoted when the driver rejects it
    GlShaderName name_;
};

struct GlBlendTarget {
    bool enable = false;
    GLenum srcColor = GL_ONE;
    GLenum dstColor = GL_ZERO;
    GLenum colorEquation = GL_FUNC_ADD;
    GLenum srcAlpha = GL_ONE;
    GLenum dstAlpha = GL_ZERO;
    GLenum alphaEquation = GL_FUNC_ADD;
    std::array<GLboolean, 4> mask{GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
};

// Fixed-function state in GL terms, resolved once at creation and applied at bindPipeline.
struct GlFixedState {
    GLenum primitive = GL_TRIANGLES;
    bool depthTest = false;
    GLenum depthFunc = GL_LESS;
    GLboolean depthMask = GL_FALSE;
    bool depthClamp = false;
    bool cull = false;
    GLenum cullFace = GL_BACK;
    rhi::DepthBias bias; // already signed by the conventions
    std::vector<GlBlendTarget> targets;
};

// What the pipeline's VAO currently references, so redundant re-binds are skipped. Valid only for
// the submit `generation` it was filled in: raw GL between submits may have changed the VAO.
struct GlVertexArrayCache {
    std::uint64_t generation = 0;
    std::vector<std::pair<GLuint, std::uint64_t>> vertexBuffers;
    GLuint indexBuffer = 0;
    std::int64_t baseInstance = -1; // value of SPIRV_Cross_BaseInstance; -1: unknown
};

class GlPipeline final : public rhi::Pipeline {
public:
    // `programs`: where linked programs are kept between processes; null: nowhere.
    GlPipeline(GlContextPtr context, const rhi::PipelineDesc& desc, const rhi::Conventions& conventions,
               const GlProgramCache* programs);

    const rhi::PipelineDesc& desc() const override { return desc_; }
    const std::vector<rhi::ShaderBinding>& bindings() const override { return bindings_; }
    GLuint program() const { return program_.get(); }
    GLuint vertexArray() const { return vertexArray_.get(); }
    const GlFixedState& state() const { return state_; }
    // SPIRV-Cross's stand-in for the base instance in gl_InstanceIndex; -1 when unused.
    GLint baseInstanceLocation() const { return baseInstanceLocation_; }
    GLsizei stride(std::uint32_t slot) const { return slot < strides_.size() ? strides_[slot] : 0; }
    GlVertexArrayCache& vertexArrayCache() const { return cache_; }

private:
    void link(const GlProgramCache* programs);
    void buildVertexArray();

    GlContextPtr context_;
    rhi::PipelineDesc desc_;
    std::vector<rhi::ShaderBinding> bindings_;
    GlProgramName program_;
    GlVertexArrayName vertexArray_;
    GlFixedState state_;
    GLint baseInstanceLocation_ = -1;
    std::vector<GLsizei> strides_;
    mutable GlVertexArrayCache cache_;
};

// A program of one compute shader.
class GlComputePipeline final : public rhi::ComputePipeline {
public:
    GlComputePipeline(GlContextPtr context, const rhi::ComputePipelineDesc& desc, const GlProgramCache* programs);

    const rhi::ComputePipelineDesc& desc() const override { return desc_; }
    GLuint program() const { return program_.get(); }

private:
    GlContextPtr context_;
    rhi::ComputePipelineDesc desc_;
    GlProgramName program_;
};

} // namespace penumbra::opengl
