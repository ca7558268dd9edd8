#include "penumbra/rhi/ValidatingDevice.hpp"

#include "DeviceLifetime.hpp"
#include "Rules.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/MemorySize.hpp"

#include <fmt/format.h>

namespace penumbra::rhi {

ValidatingDevice::ValidatingDevice(bool validate) : validate_(validate), lifetime_(std::make_shared<DeviceLifetime>())
{
}

ValidatingDevice::~ValidatingDevice() { lifetime_->alive.store(false, std::memory_order_release); }

// Out of memory is checked with validation off too: it is the machine's limit, not a misuse of the API.
std::unique_ptr<Buffer> ValidatingDevice::createBuffer(const BufferDesc& desc)
{
    checkFitsInMemory(capabilities(), describeAllocation(desc), desc.size);
    return apiCreateBuffer(desc);
}

std::unique_ptr<Texture> ValidatingDevice::createTexture(const TextureDesc& desc)
{
    if (validate_)
        checkTextureDesc(capabilities(), desc);
    checkFitsInMemory(capabilities(), describeAllocation(desc), textureBytes(desc));
    return apiCreateTexture(desc);
}

void ValidatingDevice::writeTexture(Texture& texture, std::uint32_t layer, std::uint32_t level,
                                    std::span<const std::byte> data)
{
    if (validate_)
        checkTextureUpload(texture.desc(), layer, level, data.size());
    apiWriteTexture(texture, layer, level, data);
}

std::unique_ptr<Sampler> ValidatingDevice::createSampler(const SamplerDesc& desc)
{
    if (validate_)
        checkSamplerDesc(capabilities(), desc);
    return apiCreateSampler(desc);
}

std::unique_ptr<Shader> ValidatingDevice::createShader(const ShaderSource& source)
{
    CompiledShader compiled = compileShader(source, conventions().glslHeader(), desc().pipelineCache.get());
    if (validate_ && compiled.stage == ShaderStage::Compute)
        checkWorkgroup(capabilities(), compiled);
    return apiCreateShader(std::move(compiled));
}

std::unique_ptr<Pipeline> ValidatingDevice::createPipeline(const PipelineDesc& desc)
{
    if (validate_)
        checkPipeline(capabilities(), desc);
    return apiCreatePipeline(desc);
}

std::unique_ptr<ComputePipeline> ValidatingDevice::createComputePipeline(const ComputePipelineDesc& desc)
{
    if (validate_)
        checkComputePipeline(desc);
    return apiCreateComputePipeline(desc);
}

std::unique_ptr<BindingSetLayout> ValidatingDevice::createBindingSetLayout(const BindingSetLayoutDesc& desc)
{
    if (validate_)
        checkBindingSetLayout(desc);
    return std::unique_ptr<BindingSetLayout>(new BindingSetLayout(desc));
}

std::unique_ptr<BindingSet> ValidatingDevice::createBindingSet(const BindingSetDesc& desc)
{
    if (validate_)
        checkBindingSet(capabilities(), desc);
    return apiCreateBindingSet(desc);
}

std::unique_ptr<BindingSet> ValidatingDevice::apiCreateBindingSet(const BindingSetDesc& desc)
{
    return std::unique_ptr<BindingSet>(new BindingSet(desc));
}

std::unique_ptr<Framebuffer> ValidatingDevice::createFramebuffer(const FramebufferDesc& desc)
{
    if (validate_)
        checkFramebuffer(desc);
    return apiCreateFramebuffer(desc);
}

std::unique_ptr<TimestampQueries> ValidatingDevice::createTimestampQueries(std::uint32_t count)
{
    if (validate_)
        checkTimestampQueries(capabilities(), count);
    return apiCreateTimestampQueries(count);
}

void ValidatingDevice::submit(CommandList& commands)
{
    if (!validate_) {
        auto& list = static_cast<ValidatingCommandList&>(commands);
        list.record(list.hazards_.finish());
        apiSubmit(commands);
        list.hazards_.reset();
        list.resources_.clear();
        list.computePipeline_ = nullptr;
        return;
    }
    if (!lifetime_->owns(&commands))
        throw Error("submit: the command list was not created by this device");
    auto& list = static_cast<ValidatingCommandList&>(commands);
    if (list.inPass_)
        throw Error("submit: the command list is inside a pass; call endPass() first");
    if (!list.labels_.empty())
        throw Error(fmt::format("submit: label '{}' is still open; call popLabel() first", list.labels_.back()));
    // A submit empties the list, also when it fails: recording starts from nothing either way.
    struct ForgetOnExit {
        ValidatingCommandList& list;
        ~ForgetOnExit() { list.forgetRecording(); }
    } forget{list};
    list.record(list.hazards_.finish());
    apiSubmit(commands);
}

} // namespace penumbra::rhi
