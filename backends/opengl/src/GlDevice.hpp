#pragma once

#include "GlContext.hpp"
#include "GlHandle.hpp"
#include "GlOrientation.hpp"
#include "GlProgramCache.hpp"
#include "GlStateCache.hpp"
#include "penumbra/opengl/OpenGLDevice.hpp"
#include "penumbra/rhi/ValidatingDevice.hpp"

#include <memory>
#include <optional>
#include <string>

namespace penumbra::opengl {

class GlDevice final : public rhi::ValidatingDevice {
public:
    GlDevice(const rhi::DeviceDesc& desc, const OpenGLDeviceOptions& options);
    ~GlDevice() override;

    const rhi::DeviceDesc& desc() const override { return desc_; }
    const rhi::Conventions& conventions() const override { return conventions_; }
    const rhi::Capabilities& capabilities() const override { return capabilities_; }

    std::unique_ptr<rhi::CommandList> createCommandList() override;
    std::unique_ptr<rhi::Swapchain> createSwapchain() override;
    std::vector<double> readTimestamps(const rhi::TimestampQueries& queries) override;

    std::vector<std::string> debugMessages() const override;
    void clearDebugMessages() override;

    const GlContext& context() const { return *context_; }

private:
    std::unique_ptr<rhi::Buffer> apiCreateBuffer(const rhi::BufferDesc& desc) override;
    std::unique_ptr<rhi::Texture> apiCreateTexture(const rhi::TextureDesc& desc) override;
    void apiWriteTexture(rhi::Texture& texture, std::uint32_t layer, std::uint32_t level,
                         std::span<const std::byte> data) override;
    std::unique_ptr<rhi::Sampler> apiCreateSampler(const rhi::SamplerDesc& desc) override;
    std::unique_ptr<rhi::Shader> apiCreateShader(rhi::CompiledShader compiled) override;
    std::unique_ptr<rhi::Pipeline> apiCreatePipeline(const rhi::PipelineDesc& desc) override;
    std::unique_ptr<rhi::ComputePipeline> apiCreateComputePipeline(const rhi::ComputePipelineDesc& desc) override;
    std::unique_ptr<rhi::Framebuffer> apiCreateFramebuffer(const rhi::FramebufferDesc& desc) override;
    std::unique_ptr<rhi::TimestampQueries> apiCreateTimestampQueries(std::uint32_t count) override;
    void apiSubmit(rhi::CommandList& commands) override;

    rhi::Capabilities queryCapabilities() const;
    rhi::FormatSupport formatSupport(rhi::Format format) const;
    std::uint32_t multisampleCounts(GLenum internalFormat) const;
    // State that every submit assumes; set again each time because raw GL may run between submits.
    void applySubmitDefaults();

    rhi::DeviceDesc desc_;
    std::shared_ptr<GlContext> context_;
    GlOrientation orientation_;
    rhi::Conventions conventions_;
    rhi::Capabilities capabilities_;
    std::optional<GlStateCache> cache_;
    std::optional<GlProgramCache> programs_; // with DeviceDesc::pipelineCache where the driver has binary formats
    // resolveTexture's read and draw framebuffers, the source and destination attached for each blit.
    GlFramebufferName resolveRead_, resolveDraw_;
    std::uint64_t submitCount_ = 0;
    std::optional<std::string> lost_; // the message of the reset that lost the context
};

} // namespace penumbra::opengl
