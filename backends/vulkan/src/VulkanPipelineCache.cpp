#include "VulkanPipelineCache.hpp"

#include "VulkanCheck.hpp"

#include <chrono>
#include <cstring>
#include <fmt/format.h>

namespace penumbra::vulkan {
namespace {

constexpr std::string_view kPipelineCacheKind = "vulkan";
// The cache holds every pipeline of the device, so one entry per device: its key says what the data is.
constexpr std::string_view kKey = "VkPipelineCache data";

std::string uuidText(const std::uint8_t (&uuid)[VK_UUID_SIZE])
{
    std::string text;
    for (const std::uint8_t byte : uuid)
        text += fmt::format("{:02x}", byte);
    return text;
}

} // namespace

std::string pipelineCacheDataRefusal(const VkPhysicalDeviceProperties& device, std::string_view data)
{
    VkPipelineCacheHeaderVersionOne header{};
    if (data.size() < sizeof(header))
        return fmt::format("a pipeline cache header of {} bytes, fewer than {}", data.size(), sizeof(header));
    std::memcpy(&header, data.data(), sizeof(header));
    if (header.headerSize < sizeof(header) || header.headerSize > data.size())
        return fmt::format("a pipeline cache header size of {}", header.headerSize);
    if (header.headerVersion != VK_PIPELINE_CACHE_HEADER_VERSION_ONE)
        return fmt::format("pipeline cache header version {}", int(header.headerVersion));
    if (header.vendorID != device.vendorID || header.deviceID != device.deviceID ||
        std::memcmp(header.pipelineCacheUUID, device.pipelineCacheUUID, VK_UUID_SIZE) != 0)
        return fmt::format("foreign: pipeline cache data of vendor {:#x}, device {:#x}, UUID {}; this is vendor "
                           "{:#x}, device {:#x}, UUID {}",
                           header.vendorID, header.deviceID, uuidText(header.pipelineCacheUUID), device.vendorID,
                           device.deviceID, uuidText(device.pipelineCacheUUID));
    return {};
}

VulkanPipelineCache::VulkanPipelineCache(std::shared_ptr<Context> context, std::shared_ptr<rhi::PipelineCache> disk)
    : context_(std::move(context)), disk_(std::move(disk))
{
    const VkPhysicalDeviceProperties& p = context_->properties;
    identity_ = fmt::format("Vulkan {} (vendor {:#x}, device {:#x}, driver {:#x}, pipelineCacheUUID {})", p.deviceName,
                            p.vendorID, p.deviceID, p.driverVersion, uuidText(p.pipelineCacheUUID));
    if (disk_)
        if (std::optional<std::string> stored = disk_->load(kPipelineCacheKind, identity_, kKey)) {
            // The driver checks the header too, but a cache is never trusted: data for another device is refused
            // before the driver sees it.
            if (const std::string why = pipelineCacheDataRefusal(p, *stored); !why.empty())
                disk_->refuse(kPipelineCacheKind, identity_, kKey, why);
            else
                loaded_ = std::move(*stored);
        }
    VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    info.initialDataSize = loaded_.size();
    info.pInitialData = loaded_.empty() ? nullptr : loaded_.data();
    cache_ = createOwned<UniquePipelineCache>(context_->device, vkCreatePipelineCache, info, "vkCreatePipelineCache");
    context_->pipelineCache = cache_.get();
}

VulkanPipelineCache::~VulkanPipelineCache()
{
    context_->pipelineCache = VK_NULL_HANDLE;
    if (!disk_)
        return;
    try {
        const std::string now = data();
        if (now != loaded_ && pipelineCacheDataRefusal(context_->properties, now).empty())
            disk_->store(kPipelineCacheKind, identity_, kKey, now, 0.0);
    } catch (const std::exception& e) {
        fmt::print(stderr, "penumbra: the Vulkan pipeline cache was not stored: {}\n", e.what());
    }
}

std::string VulkanPipelineCache::data() const
{
    // The two-call idiom (Vulkan 1.3 section 10.7.3 "Retrieving Pipeline Cache Data"); VK_INCOMPLETE if the cache
    // grew between the calls, which cannot happen here: pipelines are created on the device's thread.
    std::size_t size = 0;
    check(vkGetPipelineCacheData(context_->device, cache_.get(), &size, nullptr), "vkGetPipelineCacheData");
    std::string bytes(size, '\0');
    check(vkGetPipelineCacheData(context_->device, cache_.get(), &size, bytes.data()), "vkGetPipelineCacheData");
    bytes.resize(size);
    return bytes;
}

} // namespace penumbra::vulkan
