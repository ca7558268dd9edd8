#pragma once

#include "penumbra/rhi/Device.hpp"

#include <memory>
#include <string>

namespace penumbra::apps {

// DeviceDesc::validateUsage (the RHI's validation layer) for every device the tools create. On unless the
// tool's main turns it off: the penumbra tool does in release builds without --validate. Tests never touch
// it, so their devices validate.
void setToolUsageValidation(bool on);
bool toolUsageValidation();

// The configuration's description with the tools' validateUsage.
rhi::DeviceDesc toolDeviceDesc(const std::string& configuration);
// The same with the Vulkan validation layer and GL debug output as `validate` (the tools' --validate) says.
rhi::DeviceDesc toolDeviceDesc(const std::string& configuration, bool validate);
std::unique_ptr<rhi::Device> createToolDevice(const std::string& configuration);

} // namespace penumbra::apps
