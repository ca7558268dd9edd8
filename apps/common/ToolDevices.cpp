#include "ToolDevices.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/backends/Registry.hpp"

#include <atomic>
#include <cstdlib>
#include <string_view>

namespace penumbra::apps {
namespace {

std::atomic<bool> usageValidation = true;
std::shared_ptr<rhi::PipelineCache> pipelineCache; // set by main before any thread starts

} // namespace

void setToolUsageValidation(bool on) { usageValidation = on; }

bool toolUsageValidation() { return usageValidation; }

void setToolPipelineCache(std::shared_ptr<rhi::PipelineCache> cache) { pipelineCache = std::move(cache); }

const std::shared_ptr<rhi::PipelineCache>& toolPipelineCache() { return pipelineCache; }

std::shared_ptr<rhi::PipelineCache> pipelineCacheFromEnvironment()
{
    const char* setting = std::getenv("PENUMBRA_PIPELINE_CACHE");
    const std::string_view value = setting ? setting : "";
    if (value == "off")
        return nullptr;
    const std::filesystem::path folder = value.empty() ? rhi::defaultPipelineCacheFolder() : value;
    return folder.empty() ? nullptr : std::make_shared<rhi::PipelineCache>(folder);
}

rhi::DeviceDesc toolDeviceDesc(const std::string& configuration)
{
    rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration);
    desc.validateUsage = toolUsageValidation();
    desc.pipelineCache = pipelineCache;
    return desc;
}

rhi::DeviceDesc toolDeviceDesc(const std::string& configuration, bool validate)
{
    rhi::DeviceDesc desc = toolDeviceDesc(configuration);
    desc.validation = validate;
    desc.validateUsage = desc.validateUsage || validate;
    return desc;
}

std::unique_ptr<rhi::Device> createToolDevice(const std::string& configuration)
{
    return penumbra::createDevice(toolDeviceDesc(configuration));
}

} // namespace penumbra::apps
