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

struct PipelineNames {
    GLuint program = 0;
    GLuint vertexArray = 0;
};

GLuint bufferName(const rhi::Buffer& buffer);
GLuint textureName(const rhi::Texture& texture);
// GL_TEXTURE_2D or GL_TEXTURE_2D_ARRAY.
GLenum textureTarget(const rhi::Texture& texture);
GLuint samplerName(const rhi::Sampler& sampler);
GLuint framebufferName(const rhi::Framebuffer& framebuffer);
PipelineNames pipelineNames(const rhi::Pipeline& pipeline);

} // namespace penumbra::opengl
