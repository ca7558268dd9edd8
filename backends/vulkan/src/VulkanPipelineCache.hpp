#pragma once

#include "VulkanContext.hpp"

#include "penumbra/rhi/PipelineCache.hpp"

#include <memory>
#include <string>

namespace penumbra::vulkan {

// The device's VkPipelineCache, filled from the disk entry "vulkan" of an rhi::PipelineCache when one is valid
// for this device, and written back when the device goes if pipelines added to it. While it exists, the context's
// pipelines are created with it (Context::pipelineCache).
class VulkanPipelineCache {
public:
    VulkanPipelineCache(std::shared_ptr<Context> context, std::shared_ptr<rhi::PipelineCache> disk);
    // Stores the data when it changed; a failure is a note of the rhi::PipelineCache, never an exception.
    ~VulkanPipelineCache();
    VulkanPipelineCache(const VulkanPipelineCache&) = delete;
    VulkanPipelineCache& operator=(const VulkanPipelineCache&) = delete;

private:
    std::string data() const;

    std::shared_ptr<Context> context_;
    std::shared_ptr<rhi::PipelineCache> disk_;
    std::string identity_; // vendor, device, driver and pipelineCacheUUID
    std::string loaded_; // the data it started from
    UniquePipelineCache cache_;
};

// Why `data` is not pipeline cache data this device can take (Vulkan 1.3 section 10.7.4 "Pipeline Cache
// Header": VkPipelineCacheHeaderVersionOne's size, version, vendorID, deviceID and pipelineCacheUUID); empty when
// it is.
std::string pipelineCacheDataRefusal(const VkPhysicalDeviceProperties& device, std::string_view data);

} // namespace penumbra::vulkan
