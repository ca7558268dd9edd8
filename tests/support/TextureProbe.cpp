#include "TextureProbe.hpp"

#include "penumbra/rhi/Image.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <cstring>

namespace penumbra::testing {
namespace {

struct ProbeBlock {
    glm::vec4 uv; // origin, step
    glm::vec4 lod; // x
};

} // namespace

TextureProbe::TextureProbe(rhi::Device& device) : device_(device)
{
    vertex_ = device.createShader(shaders::load("fullscreen.vert"));
    fragment_ = device.createShader({rhi::ShaderStage::Fragment, R"(#version 450
layout(std140, binding = 0) uniform Probe { vec4 uv; vec4 lod; } probe;
layout(binding = 1) uniform sampler2D image;
layout(location = 0) out vec4 outColor;
void main() { outColor = textureLod(image, probe.uv.xy + probe.uv.zw * floor(gl_FragCoord.xy), probe.lod.x); }
)",
                                     "texture_probe.frag"});
    pipeline_ = device.createPipeline(
        {.vertex = vertex_.get(), .fragment = fragment_.get(), .colorTargets = {{.format = rhi::Format::RGBA32F}}});
    uniforms_ = device.createBuffer({.size = sizeof(ProbeBlock), .usage = rhi::BufferUsage::Uniform});
}

std::vector<glm::vec4> TextureProbe::sample(const rhi::Texture& texture, const rhi::Sampler& sampler,
                                            const Request& request)
{
    auto target = device_.createTexture({.width = request.width,
                                         .height = request.height,
                                         .format = rhi::Format::RGBA32F,
                                         .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment attachment{target.get(), 0};
    auto framebuffer = device_.createFramebuffer({.colors = {&attachment, 1}});
    uniforms_->writeObject(ProbeBlock{{request.origin, request.step}, glm::vec4(request.lod)});
    auto commands = device_.createCommandList();
    commands->beginPass({.framebuffer = framebuffer.get()});
    commands->bindPipeline(*pipeline_);
    commands->bindUniformBuffer(0, *uniforms_, 0, sizeof(ProbeBlock));
    commands->bindTexture(1, texture, sampler);
    commands->draw(3);
    commands->endPass();
    device_.submit(*commands);
    const rhi::Image image = rhi::readTexture(device_, *target);
    std::vector<glm::vec4> texels(std::size_t(request.width) * request.height);
    std::memcpy(texels.data(), image.bytes.data(), image.bytes.size());
    return texels;
}

} // namespace penumbra::testing
