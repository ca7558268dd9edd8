#include "VulkanContext.hpp"

#include "VulkanCheck.hpp"
#include "VulkanFormats.hpp"
#include "VulkanLayouts.hpp"
#include "VulkanRenderPass.hpp"
#include "VulkanSwapchain.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>

namespace penumbra::vulkan {

Context::Context(const rhi::DeviceDesc& d)
    : desc(d), conventions(rhi::DepthRange::ZeroToOne, d.reversedZ),
      instance(d.validation, log, d.window.glfwWindow ? windowInstanceExtensions() : std::vector<const char*>{})
{
    const PhysicalDeviceChoice choice = choosePhysicalDevice(instance.handle());
    physicalDevice = choice.device;
    queueFamily = choice.queueFamily;
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    fillCapabilities();
    createDevice();
}

// The members then go in reverse order: caches, fence, pool, the device, and teardown_ reports.
Context::~Context()
{
    teardown_.from = log.all().size();
    vkDeviceWaitIdle(device);
}

Context::TeardownReport::~TeardownReport()
{
    const std::vector<std::string> messages = log.all();
    for (std::size_t i = from; i < messages.size(); ++i)
        std::fprintf(stderr, "penumbra: while destroying the Vulkan device: %s\n", messages[i].c_str());
}

void Context::fillCapabilities()
{
    VkPhysicalDeviceFeatures features;
    vkGetPhysicalDeviceFeatures(physicalDevice, &features);
    const VkPhysicalDeviceLimits& limits = properties.limits;
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());

    const std::uint32_t v = properties.apiVersion;
    capabilities.api =
        fmt::format("Vulkan {}.{}.{}", VK_API_VERSION_MAJOR(v), VK_API_VERSION_MINOR(v), VK_API_VERSION_PATCH(v));
    capabilities.device = properties.deviceName;
    capabilities.depthClamp = features.depthClamp;
    capabilities.depthBiasClamp = features.depthBiasClamp;
    capabilities.timestamps = limits.timestampComputeAndGraphics && families[queueFamily].timestampValidBits > 0;
    capabilities.uniformBufferOffsetAlignment = std::uint32_t(limits.minUniformBufferOffsetAlignment);
    capabilities.maxUniformBufferRange = limits.maxUniformBufferRange;
    capabilities.maxTextureSize = limits.maxImageDimension2D;
    capabilities.maxTextureLayers = limits.maxImageArrayLayers;
    capabilities.cubeArrays = features.imageCubeArray;
    capabilities.maxCubeSize = limits.maxImageDimensionCube;
    capabilities.maxSamplerAnisotropy = features.samplerAnisotropy ? limits.maxSamplerAnisotropy : 1.0f;
    capabilities.deviceLossReported = true;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        capabilities.maxWorkgroupSize[axis] = limits.maxComputeWorkGroupSize[axis];
        capabilities.maxWorkgroupCount[axis] = limits.maxComputeWorkGroupCount[axis];
    }
    capabilities.maxWorkgroupInvocations = limits.maxComputeWorkGroupInvocations;
    capabilities.maxComputeSharedMemory = limits.maxComputeSharedMemorySize;
    capabilities.storageBufferOffsetAlignment = std::uint32_t(limits.minStorageBufferOffsetAlignment);
    capabilities.maxStorageBufferRange = limits.maxStorageBufferRange;
    capabilities.pipelineBinaries = true; // VkPipelineCache is core Vulkan 1.0
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memory);
    for (std::uint32_t i = 0; i < memory.memoryHeapCount; ++i)
        if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            capabilities.deviceMemoryBytes =
                std::max<std::uint64_t>(capabilities.deviceMemoryBytes, memory.memoryHeaps[i].size);
    for (rhi::Format f : rhi::allFormats)
        capabilities.formats[std::size_t(f)] = formatSupport(f);
}

rhi::FormatSupport Context::formatSupport(rhi::Format format) const
{
    const VkFormatFeatureFlags has = formatFeatures(toVkFormat(format));
    auto all = [&](VkFormatFeatureFlags wanted) { return (has & wanted) == wanted; };
    // Every texture is uploaded and copied, so each use needs the transfer features as well.
    const VkFormatFeatureFlags transfer = VK_FORMAT_FEATURE_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    const VkFormatFeatureFlags attachment = rhi::isDepthFormat(format) ? VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT
                                                                       : VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
    rhi::FormatSupport support{.sampled = all(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | transfer),
                               .linearFilter = all(VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT),
                               .renderTarget = all(attachment | transfer),
                               .storage = !rhi::isDepthFormat(format) && all(VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT)};
    if (support.renderTarget)
        support.sampleCounts = renderTargetSampleCounts(format);
    return support;
}

// The image's own sample counts (Vulkan 1.3 section 12.3, vkGetPhysicalDeviceImageFormatProperties) within the
// framebuffer limit of its aspect (section 42.1, framebufferColorSampleCounts, framebufferDepthSampleCounts),
// at most 8.
std::uint32_t Context::renderTargetSampleCounts(rhi::Format format) const
{
    const bool depth = rhi::isDepthFormat(format);
    const VkImageUsageFlags usage =
        VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
        (depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
    VkImageFormatProperties image{};
    if (vkGetPhysicalDeviceImageFormatProperties(physicalDevice, toVkFormat(format), VK_IMAGE_TYPE_2D,
                                                 VK_IMAGE_TILING_OPTIMAL, usage, 0, &image) != VK_SUCCESS)
        return VK_SAMPLE_COUNT_1_BIT;
    const VkPhysicalDeviceLimits& limits = properties.limits;
    const VkSampleCountFlags framebuffer =
        depth ? limits.framebufferDepthSampleCounts : limits.framebufferColorSampleCounts;
    const VkSampleCountFlags upToEight =
        VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_2_BIT | VK_SAMPLE_COUNT_4_BIT | VK_SAMPLE_COUNT_8_BIT;
    return std::uint32_t(image.sampleCounts & framebuffer & upToEight) | VK_SAMPLE_COUNT_1_BIT;
}

bool Context::hasDeviceExtension(const char* name) const
{
    std::uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

void Context::createDevice()
{
    // maintenance4 lets a vertex shader write outputs the fragment shader ignores (a shadow caster
    // reusing a lit vertex shader) without a validation warning.
    VkPhysicalDeviceMaintenance4Features maintenance4{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES};
    VkPhysicalDeviceFeatures2 available{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    std::vector<const char*> extensions;
    if (hasDeviceExtension(VK_KHR_MAINTENANCE_4_EXTENSION_NAME)) {
        available.pNext = &maintenance4;
        extensions.push_back(VK_KHR_MAINTENANCE_4_EXTENSION_NAME);
    }
    // Draw counts: core in Vulkan 1.2 behind the drawIndirectCount feature (Vulkan 1.3 section 21.3), else
    // VK_KHR_draw_indirect_count.
    VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    const bool core12 = std::min(properties.apiVersion, instance.apiVersion()) >= VK_API_VERSION_1_2;
    if (core12) {
        vulkan12.pNext = available.pNext;
        available.pNext = &vulkan12;
    }
    vkGetPhysicalDeviceFeatures2(physicalDevice, &available);
    if (!maintenance4.maintenance4)
        extensions.clear();
    const bool coreCount = desc.nativeDrawIndirectCount && vulkan12.drawIndirectCount;
    const bool extensionCount =
        desc.nativeDrawIndirectCount && !coreCount && hasDeviceExtension(VK_KHR_DRAW_INDIRECT_COUNT_EXTENSION_NAME);
    if (extensionCount)
        extensions.push_back(VK_KHR_DRAW_INDIRECT_COUNT_EXTENSION_NAME);
    if (desc.window.glfwWindow) {
        if (!hasDeviceExtension(VK_KHR_SWAPCHAIN_EXTENSION_NAME))
            throw rhi::Error(fmt::format("Vulkan: {} cannot present to windows (no {})", properties.deviceName,
                                         VK_KHR_SWAPCHAIN_EXTENSION_NAME));
        extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }

    VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enabled.pNext = maintenance4.maintenance4 ? &maintenance4 : nullptr;
    enabled.features.depthClamp = available.features.depthClamp;
    enabled.features.depthBiasClamp = available.features.depthBiasClamp;
    enabled.features.independentBlend = available.features.independentBlend;
    enabled.features.imageCubeArray = available.features.imageCubeArray; // every cube texture is a cube array
    enabled.features.samplerAnisotropy = available.features.samplerAnisotropy;
    enabled.features.multiDrawIndirect = available.features.multiDrawIndirect; // the draw-count emulation's
    multiDrawIndirect = available.features.multiDrawIndirect;
    maintenance4.pNext = nullptr;
    VkPhysicalDeviceVulkan12Features enabled12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    if (coreCount) {
        enabled12.drawIndirectCount = VK_TRUE;
        enabled12.pNext = enabled.pNext;
        enabled.pNext = &enabled12;
    }

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.pNext = &enabled;
    info.enabledExtensionCount = std::uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(vkCreateDevice(physicalDevice, &info, nullptr, &device), "vkCreateDevice");
    ownedDevice_ = UniqueDevice(device);
    vkGetDeviceQueue(device, queueFamily, 0, &queue);
    if (desc.validation) {
        setObjectName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetDeviceProcAddr(device, "vkSetDebugUtilsObjectNameEXT"));
        beginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
            vkGetDeviceProcAddr(device, "vkCmdBeginDebugUtilsLabelEXT"));
        endLabel =
            reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(vkGetDeviceProcAddr(device, "vkCmdEndDebugUtilsLabelEXT"));
        insertLabel = reinterpret_cast<PFN_vkCmdInsertDebugUtilsLabelEXT>(
            vkGetDeviceProcAddr(device, "vkCmdInsertDebugUtilsLabelEXT"));
    }

    if (coreCount || extensionCount) {
        drawIndirectCount = reinterpret_cast<PFN_vkCmdDrawIndirectCount>(
            vkGetDeviceProcAddr(device, coreCount ? "vkCmdDrawIndirectCount" : "vkCmdDrawIndirectCountKHR"));
        drawIndexedIndirectCount = reinterpret_cast<PFN_vkCmdDrawIndexedIndirectCount>(
            vkGetDeviceProcAddr(device,
                                coreCount ? "vkCmdDrawIndexedIndirectCount" : "vkCmdDrawIndexedIndirectCountKHR"));
    }
    capabilities.drawIndirectCount = drawIndirectCount && drawIndexedIndirectCount;

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = queueFamily;
    oneShotPool_ = createOwned<UniqueCommandPool>(device, vkCreateCommandPool, poolInfo, "vkCreateCommandPool");
    const VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    oneShotFence_ = createOwned<UniqueFence>(device, vkCreateFence, fenceInfo, "vkCreateFence");
    renderPasses_ = std::make_unique<RenderPassCache>(device);
    layouts_ = std::make_unique<LayoutCache>(device);
}

std::uint32_t Context::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted,
                                  VkMemoryPropertyFlags required) const
{
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memory);
    for (VkMemoryPropertyFlags flags : {wanted, required})
        for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
            if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags)
                return i;
    throw rhi::Error(fmt::format("Vulkan: no memory type with properties {:#x} among types {:#x}", required, typeBits));
}

void Context::nameObject(VkObjectType type, std::uint64_t handle, const std::string& name) const
{
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name.c_str();
    setObjectName_(device, &info);
}

VkFormatFeatureFlags Context::formatFeatures(VkFormat format) const
{
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(physicalDevice, format, &props);
    return props.optimalTilingFeatures;
}

void Context::submitAndWait(std::span<const VkCommandBuffer> commandBuffers, VkFence fence)
{
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = std::uint32_t(commandBuffers.size());
    submit.pCommandBuffers = commandBuffers.data();
    std::lock_guard lock(queueMutex_);
    throwIfLost();
    try {
        check(vkQueueSubmit(queue, 1, &submit, fence), "vkQueueSubmit");
        check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    } catch (const rhi::DeviceLostError& e) {
        lost_ = e.what();
        throw;
    }
    check(vkResetFences(device, 1, &fence), "vkResetFences");
}

void Context::throwIfLost() const
{
    if (lost_)
        throw rhi::DeviceLostError(*lost_);
}

void Context::runOnce(const std::function<void(VkCommandBuffer)>& record)
{
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = oneShotPool_.get();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    std::lock_guard lock(oneShotMutex_);
    check(vkAllocateCommandBuffers(device, &alloc, &commandBuffer), "vkAllocateCommandBuffers");
    struct Release {
        VkDevice device;
        VkCommandPool pool;
        VkCommandBuffer commandBuffer;
        ~Release() { vkFreeCommandBuffers(device, pool, 1, &commandBuffer); }
    } release{device, oneShotPool_.get(), commandBuffer};
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commandBuffer, &begin), "vkBeginCommandBuffer");
    record(commandBuffer);
    check(vkEndCommandBuffer(commandBuffer), "vkEndCommandBuffer");
    submitAndWait(std::span(&commandBuffer, 1), oneShotFence_.get());
}

void fullBarrier(VkCommandBuffer commandBuffer)
{
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT | VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                         VK_PIPELINE_STAGE_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0,
                         nullptr);
}

} // namespace penumbra::vulkan
