// A Vulkan layer for tests that loses the device: from the PENUMBRA_LOSE_DEVICE_AT_SUBMIT-th vkQueueSubmit of each
// device on (read when the device is made; 1 is its first submission, 0 or unset never), every vkQueueSubmit answers
// VK_ERROR_DEVICE_LOST without reaching the driver, as a GPU hang or reset would. lavapipe cannot be made to lose a
// device, and tests render through the real driver only, so the loss comes from between the two. Enabled through the
// loader's environment (VK_LAYER_PATH, VK_INSTANCE_LAYERS=VK_LAYER_PENUMBRA_device_loss), it sits above the
// validation layer the application enables, which therefore never sees the lost submissions.
// The layer interface: Khronos, "Architecture of the Vulkan Loader Interfaces", section "Layer Interface with the
// Loader" (dispatch keys, VkLayerInstanceCreateInfo / VkLayerDeviceCreateInfo chains, interface negotiation).
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <span>
#include <unordered_map>
#include <utility>
#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

namespace {

// Every dispatchable handle starts with its dispatch table; a device's queues share the device's.
template <typename Handle>
void* dispatchKey(Handle handle)
{
    return *reinterpret_cast<void**>(handle);
}

struct Instance {
    PFN_vkGetInstanceProcAddr next = nullptr;
    PFN_vkDestroyInstance destroy = nullptr;
};

struct Device {
    PFN_vkGetDeviceProcAddr next = nullptr;
    PFN_vkDestroyDevice destroy = nullptr;
    PFN_vkQueueSubmit submit = nullptr;
    unsigned long loseAt = 0;
    unsigned long submissions = 0;
};

std::mutex mutex;
std::unordered_map<void*, Instance> instances;
std::unordered_map<void*, Device> devices;

unsigned long loseAtFromEnvironment()
{
    const char* value = std::getenv("PENUMBRA_LOSE_DEVICE_AT_SUBMIT");
    return value ? std::strtoul(value, nullptr, 10) : 0;
}

// The loader's link to the next layer in a create info's pNext chain.
template <typename LinkInfo>
LinkInfo* linkInfo(const void* next, VkStructureType type)
{
    for (auto* info = static_cast<const VkBaseInStructure*>(next); info; info = info->pNext) {
        auto* link = reinterpret_cast<LinkInfo*>(const_cast<VkBaseInStructure*>(info));
        if (info->sType == type && link->function == VK_LAYER_LINK_INFO)
            return link;
    }
    return nullptr;
}

VKAPI_ATTR VkResult VKAPI_CALL CreateInstance(const VkInstanceCreateInfo* info, const VkAllocationCallbacks* allocator,
                                              VkInstance* instance)
{
    auto* link = linkInfo<VkLayerInstanceCreateInfo>(info->pNext, VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO);
    if (!link)
        return VK_ERROR_INITIALIZATION_FAILED;
    const PFN_vkGetInstanceProcAddr next = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext;
    const auto create = reinterpret_cast<PFN_vkCreateInstance>(next(VK_NULL_HANDLE, "vkCreateInstance"));
    const VkResult result = create(info, allocator, instance);
    if (result == VK_SUCCESS) {
        const std::lock_guard guard(mutex);
        instances[dispatchKey(*instance)] = {next, reinterpret_cast<PFN_vkDestroyInstance>(
                                                       next(*instance, "vkDestroyInstance"))};
    }
    return result;
}

VKAPI_ATTR void VKAPI_CALL DestroyInstance(VkInstance instance, const VkAllocationCallbacks* allocator)
{
    Instance found;
    {
        const std::lock_guard guard(mutex);
        found = instances.at(dispatchKey(instance));
        instances.erase(dispatchKey(instance));
    }
    found.destroy(instance, allocator);
}

VKAPI_ATTR VkResult VKAPI_CALL CreateDevice(VkPhysicalDevice physicalDevice, const VkDeviceCreateInfo* info,
                                            const VkAllocationCallbacks* allocator, VkDevice* device)
{
    auto* link = linkInfo<VkLayerDeviceCreateInfo>(info->pNext, VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO);
    if (!link)
        return VK_ERROR_INITIALIZATION_FAILED;
    const PFN_vkGetInstanceProcAddr nextInstance = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    const PFN_vkGetDeviceProcAddr next = link->u.pLayerInfo->pfnNextGetDeviceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext;
    const auto create = reinterpret_cast<PFN_vkCreateDevice>(nextInstance(VK_NULL_HANDLE, "vkCreateDevice"));
    const VkResult result = create(physicalDevice, info, allocator, device);
    if (result == VK_SUCCESS) {
        const std::lock_guard guard(mutex);
        devices[dispatchKey(*device)] = {next, reinterpret_cast<PFN_vkDestroyDevice>(next(*device, "vkDestroyDevice")),
                                         reinterpret_cast<PFN_vkQueueSubmit>(next(*device, "vkQueueSubmit")),
                                         loseAtFromEnvironment(), 0};
    }
    return result;
}

VKAPI_ATTR void VKAPI_CALL DestroyDevice(VkDevice device, const VkAllocationCallbacks* allocator)
{
    Device found;
    {
        const std::lock_guard guard(mutex);
        found = devices.at(dispatchKey(device));
        devices.erase(dispatchKey(device));
    }
    found.destroy(device, allocator);
}

VKAPI_ATTR VkResult VKAPI_CALL QueueSubmit(VkQueue queue, std::uint32_t count, const VkSubmitInfo* submits,
                                           VkFence fence)
{
    PFN_vkQueueSubmit submit = nullptr;
    {
        const std::lock_guard guard(mutex);
        Device& device = devices.at(dispatchKey(queue));
        ++device.submissions;
        if (device.loseAt != 0 && device.submissions >= device.loseAt)
            return VK_ERROR_DEVICE_LOST;
        submit = device.submit;
    }
    return submit(queue, count, submits, fence);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL GetDeviceProcAddr(VkDevice device, const char* name);

using Function = std::pair<const char*, PFN_vkVoidFunction>;

PFN_vkVoidFunction find(std::span<const Function> functions, const char* name)
{
    for (const auto& [function, address] : functions)
        if (std::strcmp(name, function) == 0)
            return address;
    return nullptr;
}

// The device functions this layer answers itself; every other passes through.
PFN_vkVoidFunction deviceFunction(const char* name)
{
    const Function functions[] = {
        {"vkGetDeviceProcAddr", reinterpret_cast<PFN_vkVoidFunction>(GetDeviceProcAddr)},
        {"vkDestroyDevice", reinterpret_cast<PFN_vkVoidFunction>(DestroyDevice)},
        {"vkQueueSubmit", reinterpret_cast<PFN_vkVoidFunction>(QueueSubmit)},
    };
    return find(functions, name);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL GetInstanceProcAddr(VkInstance instance, const char* name)
{
    const Function functions[] = {
        {"vkGetInstanceProcAddr", reinterpret_cast<PFN_vkVoidFunction>(GetInstanceProcAddr)},
        {"vkCreateInstance", reinterpret_cast<PFN_vkVoidFunction>(CreateInstance)},
        {"vkDestroyInstance", reinterpret_cast<PFN_vkVoidFunction>(DestroyInstance)},
        {"vkCreateDevice", reinterpret_cast<PFN_vkVoidFunction>(CreateDevice)},
    };
    if (const PFN_vkVoidFunction own = find(functions, name))
        return own;
    if (const PFN_vkVoidFunction own = deviceFunction(name))
        return own;
    if (instance == VK_NULL_HANDLE)
        return nullptr;
    const std::lock_guard guard(mutex);
    return instances.at(dispatchKey(instance)).next(instance, name);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL GetDeviceProcAddr(VkDevice device, const char* name)
{
    if (const PFN_vkVoidFunction own = deviceFunction(name))
        return own;
    const std::lock_guard guard(mutex);
    return devices.at(dispatchKey(device)).next(device, name);
}

} // namespace

extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkNegotiateLoaderLayerInterfaceVersion(VkNegotiateLayerInterface* version)
{
    if (version->loaderLayerInterfaceVersion > 2)
        version->loaderLayerInterfaceVersion = 2;
    version->pfnGetInstanceProcAddr = GetInstanceProcAddr;
    version->pfnGetDeviceProcAddr = GetDeviceProcAddr;
    version->pfnGetPhysicalDeviceProcAddr = nullptr;
    return VK_SUCCESS;
}
