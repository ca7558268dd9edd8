#pragma once

#include "VulkanHandle.hpp"
#include "VulkanInstance.hpp"

#include "penumbra/rhi/Device.hpp"

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

class RenderPassCache;
class LayoutCache;

// Everything a Vulkan object needs after creation. Resources hold a shared_ptr to it, so the
// VkDevice outlives every handle even when the rhi::Device is destroyed first.
class Context {
public:
    explicit Context(const rhi::DeviceDesc& desc);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    const rhi::DeviceDesc desc;
    const rhi::Conventions conventions;
    rhi::DebugMessageLog log; // before instance: the messenger writes into it until the instance is gone
    Instance instance;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    VkPhysicalDeviceProperties properties{};
    rhi::Capabilities capabilities;
    VkDevice device = VK_NULL_HANDLE; // owned by ownedDevice_
    VkQueue queue = VK_NULL_HANDLE;
    // What pipelines are created with: the device's VulkanPipelineCache while it exists, else none.
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;
    // What DescriptorBinder writes into the bindings of a binding set layout's descriptor set that a pipeline's
    // shaders do not read, when it writes that set from single binds: the device's own 16-byte buffer (uniform and
    // storage), 1x1 sampled and storage textures and a sampler, made before the first pipeline that lists a layout.
    struct Placeholders {
        VkBuffer buffer = VK_NULL_HANDLE;
        VkImageView sampledView = VK_NULL_HANDLE;
        VkImageLayout sampledLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        VkSampler sampler = VK_NULL_HANDLE;
        VkImageView storageView = VK_NULL_HANDLE;
    } placeholders;

    RenderPassCache& renderPasses() { return *renderPasses_; }
    LayoutCache& layouts() { return *layouts_; }

    // A memory type allowed by typeBits with `wanted` properties, else one with `required`.
    std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted,
                             VkMemoryPropertyFlags required) const;
    VkFormatFeatureFlags formatFeatures(VkFormat format) const;
    // Gives a handle its debugName, so validation messages say which object they mean.
    template <typename Handle>
    void setName(VkObjectType type, Handle handle, const std::string& name) const
    {
        if (setObjectName_ && !name.empty())
            nameObject(type, reinterpret_cast<std::uint64_t>(handle), name);
    }

    // Submits command buffers in order, signals `fence` and waits for it. Once the device is lost (a DeviceLostError
    // from here), every later submission raises that error again before the API is called.
    void submitAndWait(std::span<const VkCommandBuffer> commandBuffers, VkFence fence);
    // Raises the loss that submitAndWait met, if any: what a command list checks before it ends its recording.
    void throwIfLost() const;
    // Records with `record` into a one-shot command buffer, submits and waits (uploads, layout setup).
    void runOnce(const std::function<void(VkCommandBuffer)>& record);

private:
    bool hasDeviceExtension(const char* name) const;
    void nameObject(VkObjectType type, std::uint64_t handle, const std::string& name) const;
    void createDevice();
    void fillCapabilities();
    rhi::FormatSupport formatSupport(rhi::Format format) const;
    std::uint32_t renderTargetSampleCounts(rhi::Format format) const;

    PFN_vkSetDebugUtilsObjectNameEXT setObjectName_ = nullptr;

public:
    // VK_EXT_debug_utils's command labels, where the instance has the extension (with validation); else null.
    PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT endLabel = nullptr;
    PFN_vkCmdInsertDebugUtilsLabelEXT insertLabel = nullptr;
    // Draw counts read on the GPU (core drawIndirectCount feature or VK_KHR_draw_indirect_count), where the device
    // has them and DeviceDesc::nativeDrawIndirectCount asks for them; else null, and command lists emulate them.
    PFN_vkCmdDrawIndirectCount drawIndirectCount = nullptr;
    // Indirect draws of more than one command (the multiDrawIndirect feature).
    bool multiDrawIndirect = false;
    PFN_vkCmdDrawIndexedIndirectCount drawIndexedIndirectCount = nullptr;

private:
    std::mutex queueMutex_;
    std::optional<std::string> lost_; // the loss submitAndWait met
    std::mutex oneShotMutex_;
    // What the validation layer says while the device is destroyed (its object tracker names every
    // object still alive then) reaches no rhi::Device any more: this writes it to standard error.
    // Declared before ownedDevice_, so it runs after vkDestroyDevice.
    struct TeardownReport {
        const rhi::DebugMessageLog& log;
        std::size_t from = 0; // messages before this index were the device's to report
        ~TeardownReport();
    } teardown_{log};
    // Declared before everything made from it, so that it is destroyed after them.
    UniqueDevice ownedDevice_;
    UniqueCommandPool oneShotPool_;
    UniqueFence oneShotFence_;
    std::unique_ptr<RenderPassCache> renderPasses_;
    std::unique_ptr<LayoutCache> layouts_;
};

// A barrier between everything before and everything after, host reads included: simple and
// always correct, which matters more here than the last bit of GPU overlap.
void fullBarrier(VkCommandBuffer commandBuffer);

} // namespace penumbra::vulkan
