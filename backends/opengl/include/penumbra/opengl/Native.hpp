#pragma once

// Native GL objects behind RHI objects, for code that compares the RHI with hand-written GL on
// the same objects (the draw-call benchmark). Every function throws rhi::Error when given an
// object of another backend. The device re-applies all of its GL state at each submit, so raw GL
// calls between submits cannot confuse it; raw calls must first make the device's context current.

#include "penumbra/opengl/GlFunctions.hpp"
#include "penumbra/rhi/Device.hpp"

namespace penumbra::opengl {

// The device's loaded entry points; valid while the device or any of its objects lives.
const GlFunctions& glFunctions(const rhi::Device& device);

// Makes the device's context current on the calling thread (a no-op when it already is).
void makeCurrent(const rhi::Device& device);

// The GL names of a pipeline: its program and its vertex array.
struct PipelineNames {
    GLuint program = 0;
    GLuint vertexArray = 0;
};

// The GL buffer name behind an RHI buffer of an OpenGL device.
GLuint bufferName(const rhi::Buffer& buffer);
// The GL texture name behind an RHI texture of an OpenGL device.
GLuint textureName(const rhi::Texture& texture);
// GL_TEXTURE_2D or GL_TEXTURE_2D_ARRAY.
GLenum textureTarget(const rhi::Texture& texture);
// The GL sampler name behind an RHI sampler of an OpenGL device.
GLuint samplerName(const rhi::Sampler& sampler);
// The GL framebuffer name behind an RHI framebuffer of an OpenGL device.
GLuint framebufferName(const rhi::Framebuffer& framebuffer);
// The GL program and vertex array behind an RHI pipeline of an OpenGL device.
PipelineNames pipelineNames(const rhi::Pipeline& pipeline);
// The GL program behind an RHI compute pipeline of an OpenGL device.
GLuint programName(const rhi::ComputePipeline& pipeline);

} // namespace penumbra::opengl
