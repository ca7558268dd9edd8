#include "ToolDevices.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/backends/Registry.hpp"

#include <atomic>

namespace penumbra::apps {
namespace {

std::atomic<bool> usageValidation = true;

} // namespace

void setToolUsageValidation(bool on) { usageValidation = on; }

bool toolUsageValidation() { return usageValidation; }

rhi::DeviceDesc toolDeviceDesc(const std::string& configuration)
{
    rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration);
    desc.validateUsage = toolUsageValidation();
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
