#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/PipelineCache.hpp"

#include <memory>
#include <string>

namespace penumbra::apps {

// DeviceDesc::validateUsage (the RHI's validation layer) for every device the tools create. On unless the
// tool's main turns it off: the penumbra tool does in release builds without --validate. Tests never touch
// it, so their devices validate.
void setToolUsageValidation(bool on);
bool toolUsageValidation();

// DeviceDesc::pipelineCache for every device the tools create; null (none) unless the tool's main sets one.
void setToolPipelineCache(std::shared_ptr<rhi::PipelineCache> cache);
const std::shared_ptr<rhi::PipelineCache>& toolPipelineCache();
// The tools' pipeline cache as PENUMBRA_PIPELINE_CACHE says: unset or empty, the user's cache folder
// (rhi::defaultPipelineCacheFolder()); "off", none; anything else, that folder.
std::shared_ptr<rhi::PipelineCache> pipelineCacheFromEnvironment();

// The configuration's description with the tools' validateUsage and pipeline cache.
rhi::DeviceDesc toolDeviceDesc(const std::string& configuration);
// The same with the Vulkan validation layer and GL debug output as `validate` (the tools' --validate) says.
rhi::DeviceDesc toolDeviceDesc(const std::string& configuration, bool validate);
std::unique_ptr<rhi::Device> createToolDevice(const std::string& configuration);

} // namespace penumbra::apps
