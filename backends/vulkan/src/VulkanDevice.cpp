#include "VulkanDevice.hpp"

#include "VulkanBindingSet.hpp"
#include "VulkanCheck.hpp"
#include "VulkanCommandList.hpp"
#include "VulkanPipeline.hpp"
#include "VulkanRenderPass.hpp"
#include "VulkanResources.hpp"
#include "VulkanSwapchain.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/vulkan/VulkanDevice.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace penumbra::vulkan {

VulkanDevice::VulkanDevice(const rhi::DeviceDesc& desc)
    : ValidatingDevice(desc.validateUsage), context_(std::make_shared<Context>(desc)), staging_(context_)
{
    if (desc.pipelineCache)
        pipelineCache_.emplace(context_, desc.pipelineCache);
}

std::unique_ptr<rhi::Buffer> VulkanDevice::apiCreateBuffer(const rhi::BufferDesc& desc)
{
    return std::make_unique<VulkanBuffer>(context_, desc);
}

std::unique_ptr<rhi::Texture> VulkanDevice::apiCreateTexture(const rhi::TextureDesc& desc)
{
    return std::make_unique<VulkanTexture>(context_, desc);
}

void VulkanDevice::apiWriteTexture(rhi::Texture& texture, std::uint32_t layer, std::uint32_t level,
                                   std::span<const std::byte> data)
{
    auto& target = vulkanObject<VulkanTexture>(texture, "writeTexture: the texture");
    staging_.use(data.size(), [&](MappedBuffer& staging) { target.upload(layer, level, data, staging); });
}

std::unique_ptr<rhi::Sampler> VulkanDevice::apiCreateSampler(const rhi::SamplerDesc& desc)
{
    return std::make_unique<VulkanSampler>(context_, desc);
}

std::unique_ptr<rhi::Shader> VulkanDevice::apiCreateShader(rhi::CompiledShader compiled)
{
    return std::make_unique<VulkanShader>(context_, std::move(compiled));
}

std::unique_ptr<rhi::Pipeline> VulkanDevice::apiCreatePipeline(const rhi::PipelineDesc& desc)
{
    makePlaceholders(!desc.bindingSetLayouts.empty());
    return std::make_unique<VulkanPipeline>(context_, desc);
}

std::unique_ptr<rhi::ComputePipeline> VulkanDevice::apiCreateComputePipeline(const rhi::ComputePipelineDesc& desc)
{
    makePlaceholders(!desc.bindingSetLayouts.empty());
    return std::make_unique<VulkanComputePipeline>(context_, desc);
}

// lavapipe (Mesa 22.3, lvp_execute.c: handle_descriptor_sets fills every binding of a bound set for every stage of
// its layout, and fill_sampler_view_stage reads the image view of a descriptor never written) crashes on a bound set
// with a binding left unwritten, which Vulkan allows where the pipeline does not statically use it (the valid usage
// of vkCmdDraw, Vulkan 1.3 section 21.3: descriptors must be valid "if they are statically used"); a set written
// from single binds therefore fills every binding, those the shaders do not read with these.
void VulkanDevice::makePlaceholders(bool listsLayouts)
{
    if (!listsLayouts || placeholderBuffer_)
        return;
    placeholderBuffer_ = std::make_unique<VulkanBuffer>(context_, rhi::BufferDesc{.size = 16,
                                                                                  .usage = rhi::BufferUsage::Uniform |
                                                                                           rhi::BufferUsage::Storage,
                                                                                  .debugName = "placeholder"});
    placeholderTexture_ =
        std::make_unique<VulkanTexture>(context_,
                                        rhi::TextureDesc{.width = 1, .height = 1, .debugName = "placeholder"});
    placeholderStorage_ =
        std::make_unique<VulkanTexture>(context_, rhi::TextureDesc{.width = 1,
                                                                   .height = 1,
                                                                   .usage = rhi::TextureUsage::Storage,
                                                                   .debugName = "placeholder (storage)"});
    placeholderSampler_ = std::make_unique<VulkanSampler>(context_, rhi::SamplerDesc{.debugName = "placeholder"});
    const auto& texture = static_cast<const VulkanTexture&>(*placeholderTexture_);
    context_->placeholders = {static_cast<const VulkanBuffer&>(*placeholderBuffer_).handle(), texture.sampledView(),
                              texture.restingLayout(), static_cast<const VulkanSampler&>(*placeholderSampler_).handle(),
                              static_cast<const VulkanTexture&>(*placeholderStorage_).storageView(0)};
}

std::unique_ptr<rhi::BindingSet> VulkanDevice::apiCreateBindingSet(const rhi::BindingSetDesc& desc)
{
    return std::make_unique<VulkanBindingSet>(context_, desc);
}

std::unique_ptr<rhi::Framebuffer> VulkanDevice::apiCreateFramebuffer(const rhi::FramebufferDesc& desc)
{
    return std::make_unique<VulkanFramebuffer>(context_, desc);
}

std::unique_ptr<rhi::TimestampQueries> VulkanDevice::apiCreateTimestampQueries(std::uint32_t count)
{
    return std::make_unique<VulkanTimestampQueries>(context_, count);
}

std::unique_ptr<rhi::CommandList> VulkanDevice::createCommandList()
{
    return std::make_unique<VulkanCommandList>(*this, context_);
}

std::unique_ptr<rhi::Swapchain> VulkanDevice::createSwapchain() { return std::make_unique<VulkanSwapchain>(context_); }

void VulkanDevice::apiSubmit(rhi::CommandList& commands)
{
    auto& list = vulkanObject<VulkanCommandList>(commands, "submit: the command list");
    context_->throwIfLost(); // before the list ends its recording, so that it stays as it was
    list.submit();
    if (context_->desc.throwOnDebugMessage)
        context_->log.raiseUnreported("Vulkan validation");
}

std::vector<double> VulkanDevice::readTimestamps(const rhi::TimestampQueries& queries)
{
    return vulkanObject<const VulkanTimestampQueries>(queries, "readTimestamps: the queries").readNanoseconds();
}

std::unique_ptr<rhi::Device> createVulkanDevice(const rhi::DeviceDesc& desc)
{
    if (desc.backend != "vulkan")
        throw rhi::Error(fmt::format("createVulkanDevice: DeviceDesc::backend is '{}', not 'vulkan'", desc.backend));
    // [0, 1] is Vulkan's native range; [-1, 1] would need VK_EXT_depth_clip_control, which this backend does not use.
    if (desc.depthRange != rhi::DepthRange::ZeroToOne)
        throw rhi::UnsupportedError("Vulkan: the [-1, 1] depth range (DepthRange::MinusOneToOne) is not offered");
    return std::make_unique<VulkanDevice>(desc);
}

} // namespace penumbra::vulkan
