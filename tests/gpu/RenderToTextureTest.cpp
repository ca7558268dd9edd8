#include "GpuTesting.hpp"
#include "TestPattern.hpp"

#include "penumbra/shaders/ShaderLibrary.hpp"

#include <glm/vec2.hpp>

namespace penumbra::testing {
namespace {

// Draws a full-screen triangle whose fragments output texture(image, uv): either the
// interpolated uv of fullscreen.vert, or one fixed probe coordinate.
class TextureViewer {
public:
    explicit TextureViewer(rhi::Device& device) : device_(device)
    {
        vertex_ = device.createShader(shaders::load("fullscreen.vert"));
        fragment_ = device.createShader({rhi::ShaderStage::Fragment, R"(#version 450
layout(location = 1) in vec2 vUv;
layout(std140, binding = 0) uniform Probe { vec2 uv; float useProbe; } probe;
layout(binding = 1) uniform sampler2D image;
layout(location = 0) out vec4 outColor;
void main() { outColor = texture(image, probe.useProbe > 0.5 ? probe.uv : vUv); }
)",
                                         "texture_viewer.frag"});
        pipeline_ = device.createPipeline(
            {.vertex = vertex_.get(), .fragment = fragment_.get(), .colorTargets = {{.format = rhi::Format::RGBA8}}});
        sampler_ = device.createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});
        uniforms_ = device.createBuffer({.size = 16, .usage = rhi::BufferUsage::Uniform});
    }

    rhi::Image view(const rhi::Texture& texture, std::uint32_t size, std::optional<glm::vec2> probe = {})
    {
        auto target = device_.createTexture({.width = size, .height = size, .usage = rhi::TextureUsage::RenderTarget});
        const rhi::Attachment attachment{target.get(), 0};
        auto framebuffer = device_.createFramebuffer({.colors = {&attachment, 1}});
        const glm::vec4 block(probe.value_or(glm::vec2(0.0f)), probe ? 1.0f : 0.0f, 0.0f);
        uniforms_->writeObject(block);
        auto commands = device_.createCommandList();
        commands->beginPass({.framebuffer = framebuffer.get()});
        commands->bindPipeline(*pipeline_);
        commands->bindUniformBuffer(0, *uniforms_, 0, 16);
        commands->bindTexture(1, texture, *sampler_);
        commands->draw(3);
        commands->endPass();
        device_.submit(*commands);
        return rhi::readTexture(device_, *target);
    }

private:
    rhi::Device& device_;
    std::unique_ptr<rhi::Shader> vertex_, fragment_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
    std::unique_ptr<rhi::Sampler> sampler_;
    std::unique_ptr<rhi::Buffer> uniforms_;
};

using RenderToTextureTest = GpuTest;

TEST_F(RenderToTextureTest, TopLeftMarkerIsSampledAtVZero)
{
    pattern::PatternRenderer renderer(*device, {.width = 32, .height = 32, .sampled = true});
    renderer.render(pattern::testPattern());
    TextureViewer viewer(*device);
    const Rgba red{255, 0, 0, 255}, blue{0, 0, 255, 255};
    const rhi::Image nearTop = viewer.view(renderer.colorTexture(), 1, glm::vec2(0.1f, 0.05f));
    EXPECT_EQ(pixel(nearTop, 0, 0), red) << describe(pixel(nearTop, 0, 0));
    const rhi::Image nearBottom = viewer.view(renderer.colorTexture(), 1, glm::vec2(0.05f, 0.95f));
    EXPECT_EQ(pixel(nearBottom, 0, 0), blue) << describe(pixel(nearBottom, 0, 0));
}

TEST_F(RenderToTextureTest, SampledCopyEqualsTheRenderedTexture)
{
    pattern::PatternRenderer renderer(*device, {.width = 32, .height = 32, .sampled = true});
    renderer.render(pattern::testPattern());
    const rhi::Image rendered = renderer.color();
    const rhi::Image viewed = TextureViewer(*device).view(renderer.colorTexture(), 32);
    EXPECT_TRUE(rendered.bytes == viewed.bytes) << savePicture(rendered, configuration() + "/rtt-rendered") << " vs "
                                                << savePicture(viewed, configuration() + "/rtt-viewed");
}

} // namespace
} // namespace penumbra::testing
