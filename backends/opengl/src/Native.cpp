#include "penumbra/opengl/Native.hpp"

#include "GlDevice.hpp"
#include "GlPipeline.hpp"
#include "GlResources.hpp"

namespace penumbra::opengl {

const GlFunctions& glFunctions(const rhi::Device& device)
{
    return glObject<const GlDevice>(device, "device").context().gl();
}

void makeCurrent(const rhi::Device& device) { glObject<const GlDevice>(device, "device").context().makeCurrent(); }

GLuint bufferName(const rhi::Buffer& buffer) { return glObject<const GlBuffer>(buffer, "buffer").name(); }

GLuint textureName(const rhi::Texture& texture) { return glObject<const GlTexture>(texture, "texture").name(); }

GLenum textureTarget(const rhi::Texture& texture) { return glObject<const GlTexture>(texture, "texture").target(); }

GLuint samplerName(const rhi::Sampler& sampler) { return glObject<const GlSampler>(sampler, "sampler").name(); }

GLuint framebufferName(const rhi::Framebuffer& framebuffer)
{
    return glObject<const GlFramebuffer>(framebuffer, "framebuffer").name();
}

PipelineNames pipelineNames(const rhi::Pipeline& pipeline)
{
    const auto& p = glObject<const GlPipeline>(pipeline, "pipeline");
    return {p.program(), p.vertexArray()};
}

GLuint programName(const rhi::ComputePipeline& pipeline)
{
    return glObject<const GlComputePipeline>(pipeline, "compute pipeline").program();
}

} // namespace penumbra::opengl
