#include "Compositor.hpp"

#include "penumbra/shaders/ShaderLibrary.hpp"

namespace penumbra::viewer {
namespace {

constexpr std::uint32_t kPictureBinding = 0;

} // namespace

Compositor::Compositor(rhi::Device& device)
    : device_(device), vertex_(device.createShader(shaders::load("fullscreen.vert"))),
      fragment_(device.createShader(shaders::load("picture.frag", {{"BINDING_PICTURE", kPictureBinding}}))),
      // Nearest: at equal sizes every pixel takes its own texel, so the window shows the scene's bytes.
      sampler_(device.createSampler(
          {.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest, .debugName = "composed picture"})),
      commands_(device.createCommandList())
{
    rhi::PipelineDesc desc;
    desc.vertex = vertex_.get();
    desc.fragment = fragment_.get();
    desc.colorTargets = {{kFormat}};
    desc.debugName = "compose picture";
    pipeline_ = device.createPipeline(desc);
}

void Compositor::compose(const rhi::Texture& scene, rhi::Extent size,
                         const std::function<void(rhi::CommandList&)>& drawOnTop)
{
    if (!image_ || image_->desc().width != size.width || image_->desc().height != size.height) {
        target_.reset();
        image_ = device_.createTexture({.width = size.width,
                                        .height = size.height,
                                        .format = kFormat,
                                        .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                        .debugName = "composed window picture"});
        const rhi::Attachment color{image_.get(), 0};
        target_ = device_.createFramebuffer({.colors = {&color, 1}, .debugName = "composed window picture"});
    }
    rhi::CommandList& commands = *commands_;
    commands.beginPass({.framebuffer = target_.get(), .clearColor = std::nullopt, .clearDepth = false});
    commands.bindPipeline(*pipeline_);
    commands.bindTexture(kPictureBinding, scene, *sampler_);
    commands.draw(3);
    if (drawOnTop)
        drawOnTop(commands);
    commands.endPass();
    device_.submit(commands);
}

} // namespace penumbra::viewer
