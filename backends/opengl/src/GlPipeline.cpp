#include "GlPipeline.hpp"

#include "GlFormats.hpp"
#include "GlOrientation.hpp"
#include "GlProgramCache.hpp"
#include "penumbra/rhi/BackendSupport.hpp"

#include <chrono>
#include <fmt/format.h>
#include <spirv_cross/spirv_glsl.hpp>

namespace penumbra::opengl {
namespace {

std::string crossCompile(const rhi::CompiledShader& compiled, const GlOrientation& orientation)
{
    try {
        spirv_cross::CompilerGLSL compiler(compiled.spirv);
        spirv_cross::CompilerGLSL::Options options = compiler.get_common_options();
        options.version = 450;
        options.es = false;
        options.vulkan_semantics = false;
        options.enable_420pack_extension = true;
        options.vertex.flip_vert_y = compiled.stage == rhi::ShaderStage::Vertex && orientation.flipVertexY();
        // The conventions' projections already target the device's depth range.
        options.vertex.fixup_clipspace = false;
        compiler.set_common_options(options);
        return compiler.compile();
    } catch (const spirv_cross::CompilerError& e) {
        throw rhi::Error(
            fmt::format("{}: SPIRV-Cross cannot translate the SPIR-V to GLSL: {}", compiled.name, e.what()));
    }
}

GLenum glShaderStage(rhi::ShaderStage stage)
{
    switch (stage) {
    case rhi::ShaderStage::Vertex:
        return GL_VERTEX_SHADER;
    case rhi::ShaderStage::Fragment:
        return GL_FRAGMENT_SHADER;
    case rhi::ShaderStage::Compute:
        break;
    }
    return GL_COMPUTE_SHADER;
}

std::string shaderLog(const GlFunctions& gl, GLuint shader)
{
    GLint length = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    gl.GetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    return log.c_str();
}

std::string programLog(const GlFunctions& gl, GLuint program)
{
    GLint length = 0;
    gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    gl.GetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
    return log.c_str();
}

GlFixedState fixedState(const rhi::PipelineDesc& desc, const rhi::Conventions& conventions)
{
    GlFixedState s;
    s.primitive = glPrimitive(desc.topology);
    s.depthTest = desc.depth.test;
    s.depthFunc = glCompareFunc(conventions.depthCompareOp(desc.depth.compare));
    s.depthMask = desc.depth.write ? GL_TRUE : GL_FALSE;
    s.depthClamp = desc.depth.clamp;
    s.cull = desc.cull != rhi::CullMode::None;
    s.cullFace = desc.cull == rhi::CullMode::Front ? GL_FRONT : GL_BACK;
    s.bias = rhi::signedDepthBias(conventions, desc.depth.bias);
    for (const rhi::ColorTarget& c : desc.colorTargets) {
        const rhi::BlendState& b = c.blend;
        auto bit = [&](rhi::ColorMask m) -> GLboolean { return rhi::hasFlag(c.writeMask, m) ? GL_TRUE : GL_FALSE; };
        s.targets.push_back(
            {b.enable,
             glBlendFactor(b.srcColor),
             glBlendFactor(b.dstColor),
             glBlendEquation(b.colorOp),
             glBlendFactor(b.srcAlpha),
             glBlendFactor(b.dstAlpha),
             glBlendEquation(b.alphaOp),
             {bit(rhi::ColorMask::R), bit(rhi::ColorMask::G), bit(rhi::ColorMask::B), bit(rhi::ColorMask::A)}});
    }
    return s;
}

// Links `program` from `shaders`: from the binary `programs` keeps for their GLSL where it has a valid one, else
// by the driver (then kept there). Returns whether the link succeeded.
bool linkProgram(const GlFunctions& gl, GLuint program, std::initializer_list<const GlShader*> shaders,
                 const GlProgramCache* programs)
{
    std::string key;
    if (programs) {
        for (const GlShader* shader : shaders)
            key += fmt::format("{}\n{}\n", int(shader->compiled().stage), shader->glsl());
        if (programs->load(gl, program, key))
            return true;
        programs->prepare(gl, program);
    }
    const auto start = std::chrono::steady_clock::now();
    for (const GlShader* shader : shaders)
        gl.AttachShader(program, shader->name());
    gl.LinkProgram(program);
    for (const GlShader* shader : shaders)
        gl.DetachShader(program, shader->name());
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - start;
    if (ok && programs)
        programs->store(gl, program, key, spent.count());
    return ok == GL_TRUE;
}

} // namespace

GlShader::GlShader(GlContextPtr context, rhi::CompiledShader compiled, const GlOrientation& orientation)
    : context_(std::move(context)), compiled_(std::move(compiled)), glsl_(crossCompile(compiled_, orientation))
{
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    name_ = GlShaderName(*context_, gl.CreateShader(glShaderStage(compiled_.stage)));
    const GLuint shader = name_.get();
    const char* text = glsl_.c_str();
    gl.ShaderSource(shader, 1, &text, nullptr);
    gl.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok)
        throw rhi::Error(fmt::format("{}: the GL driver rejected the GLSL made by SPIRV-Cross:\n{}\n--- GLSL ---\n{}",
                                     compiled_.name, shaderLog(gl, shader), glsl_));
    gl.ObjectLabel(GL_SHADER, shader, GLsizei(compiled_.name.size()), compiled_.name.c_str());
}

GlPipeline::GlPipeline(GlContextPtr context, const rhi::PipelineDesc& desc, const rhi::Conventions& conventions,
                       const GlProgramCache* programs)
    : context_(std::move(context)), desc_(desc), bindings_(rhi::pipelineBindings(desc)),
      state_(fixedState(desc, conventions))
{
    context_->makeCurrent();
    link(programs);
    buildVertexArray();
}

void GlPipeline::link(const GlProgramCache* programs)
{
    const GlFunctions& gl = context_->gl();
    const auto& vertex = glObject<const GlShader>(*desc_.vertex, "vertex shader");
    const auto& fragment = glObject<const GlShader>(*desc_.fragment, "fragment shader");
    program_ = GlProgramName(*context_, gl.CreateProgram());
    const GLuint program = program_.get();
    if (!linkProgram(gl, program, {&vertex, &fragment}, programs))
        throw rhi::Error(fmt::format("pipeline '{}': linking {} and {} failed:\n{}", desc_.debugName,
                                     vertex.compiled().name, fragment.compiled().name, programLog(gl, program)));
    baseInstanceLocation_ = gl.GetUniformLocation(program, "SPIRV_Cross_BaseInstance");
    if (!desc_.debugName.empty())
        gl.ObjectLabel(GL_PROGRAM, program, GLsizei(desc_.debugName.size()), desc_.debugName.c_str());
}

void GlPipeline::buildVertexArray()
{
    const GlFunctions& gl = context_->gl();
    vertexArray_ = createName<GlVertexArrayName>(*context_, gl.CreateVertexArrays);
    const GLuint vertexArray = vertexArray_.get();
    const rhi::VertexLayout& layout = desc_.vertexLayout;
    for (std::size_t slot = 0; slot < layout.buffers.size(); ++slot) {
        strides_.push_back(GLsizei(layout.buffers[slot].stride));
        gl.VertexArrayBindingDivisor(vertexArray, GLuint(slot), layout.buffers[slot].perInstance ? 1 : 0);
    }
    for (const rhi::VertexAttribute& a : layout.attributes) {
        // The validation layer refuses this first; with DeviceDesc::validateUsage off it is what stops the
        // VAO from reading a slot without a stride (and what PipelineLeakTest breaks creation with).
        if (a.buffer >= layout.buffers.size())
            throw rhi::Error(fmt::format("pipeline '{}': attribute {} reads vertex buffer slot {}, which the layout "
                                         "does not declare",
                                         desc_.debugName, a.location, a.buffer));
        const GlVertexFormat f = glVertexFormat(a.format);
        gl.EnableVertexArrayAttrib(vertexArray, a.location);
        gl.VertexArrayAttribFormat(vertexArray, a.location, f.size, f.type, f.normalized, a.offset);
        gl.VertexArrayAttribBinding(vertexArray, a.location, a.buffer);
    }
    cache_.vertexBuffers.assign(strides_.size(), {0, 0});
    if (!desc_.debugName.empty())
        gl.ObjectLabel(GL_VERTEX_ARRAY, vertexArray, GLsizei(desc_.debugName.size()), desc_.debugName.c_str());
}

GlComputePipeline::GlComputePipeline(GlContextPtr context, const rhi::ComputePipelineDesc& desc,
                                     const GlProgramCache* programs)
    : ComputePipeline(desc.compute->compiled()), context_(std::move(context)), desc_(desc)
{
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    const auto& shader = glObject<const GlShader>(*desc_.compute, "compute shader");
    program_ = GlProgramName(*context_, gl.CreateProgram());
    const GLuint program = program_.get();
    if (!linkProgram(gl, program, {&shader}, programs))
        throw rhi::Error(fmt::format("compute pipeline '{}': linking {} failed:\n{}", desc_.debugName,
                                     shader.compiled().name, programLog(gl, program)));
    if (!desc_.debugName.empty())
        gl.ObjectLabel(GL_PROGRAM, program, GLsizei(desc_.debugName.size()), desc_.debugName.c_str());
}

} // namespace penumbra::opengl
