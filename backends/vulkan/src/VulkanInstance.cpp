#include "VulkanInstance.hpp"

#include "VulkanCheck.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <optional>

namespace penumbra::vulkan {
namespace {

constexpr const char* validationLayer = "VK_LAYER_KHRONOS_validation";

std::string_view severityName(VkDebugUtilsMessageSeverityFlagBitsEXT severity)
{
    return severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
}

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user)
{
    // The command buffer's open labels (CommandList::pushLabel) say which pass a message is about. The layer
    // (1.3.239) lists each label twice in a row, so a label equal to the one before is left out.
    std::string labels;
    const char* previous = nullptr;
    for (std::uint32_t i = data->cmdBufLabelCount; i > 0; --i) {
        const char* name = data->pCmdBufLabels[i - 1].pLabelName;
        if (previous && std::strcmp(previous, name) == 0)
            continue;
        labels += fmt::format("{}{}", labels.empty() ? " [labels: " : " > ", name);
        previous = name;
    }
    static_cast<rhi::DebugMessageLog*>(user)->record(
        fmt::format("vulkan {}: {}{}", severityName(severity), data->pMessage, labels.empty() ? "" : labels + "]"));
    return VK_FALSE;
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(rhi::DebugMessageLog& log)
{
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = onDebugMessage;
    info.pUserData = &log;
    return info;
}

bool hasLayer(const char* name)
{
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

std::uint32_t loaderVersion()
{
    std::uint32_t version = VK_API_VERSION_1_0;
    if (vkEnumerateInstanceVersion(&version) != VK_SUCCESS)
        return VK_API_VERSION_1_0;
    return version;
}

std::string versionString(std::uint32_t v)
{
    return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(v), VK_API_VERSION_MINOR(v), VK_API_VERSION_PATCH(v));
}

std::optional<std::uint32_t> graphicsQueueFamily(VkPhysicalDevice device)
{
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (std::uint32_t i = 0; i < count; ++i)
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)
            return i;
    return std::nullopt;
}

} // namespace

Instance::Instance(bool validation, rhi::DebugMessageLog& log, std::vector<const char*> extensions)
{
    const std::uint32_t loader = loaderVersion();
    if (loader < VK_API_VERSION_1_1)
        throw rhi::Error(
            fmt::format("Vulkan: the loader offers Vulkan {}; Penumbra needs 1.1 or newer", versionString(loader)));
    apiVersion_ = std::min(loader, VK_API_VERSION_1_3);

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "Penumbra";
    app.pEngineName = "Penumbra";
    app.apiVersion = apiVersion_;

    std::vector<const char*> layers;
    // Chained into the create info so that instance creation and destruction are reported too.
    VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(log);
    // Synchronization validation on with the rest: it reports the hazards a missing or too narrow barrier leaves
    // (the layer's "Synchronization Validation" guide, VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT),
    // which lavapipe, running commands in order, would forgive.
    const VkValidationFeatureEnableEXT enabledFeatures[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.pNext = &debugInfo;
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enabledFeatures;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    if (validation) {
        if (!hasLayer(validationLayer))
            throw rhi::Error(fmt::format("Vulkan: validation was requested but {} is not installed "
                                         "(Debian package vulkan-validationlayers)",
                                         validationLayer));
        layers.push_back(validationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
        info.pNext = &features;
    }
    info.enabledLayerCount = std::uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = std::uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();

    VkInstance instance = VK_NULL_HANDLE;
    const VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw rhi::Error("Vulkan: no driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); "
                         "install mesa-vulkan-drivers for lavapipe");
    check(result, "vkCreateInstance");
    instance_ = UniqueInstance(instance);

    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
        check(create && destroy ? create(instance, &debugInfo, nullptr, &messenger) : VK_ERROR_EXTENSION_NOT_PRESENT,
              "vkCreateDebugUtilsMessengerEXT");
        messenger_ = UniqueMessenger(instance, messenger, destroy);
    }
}

PhysicalDeviceChoice choosePhysicalDevice(VkInstance instance)
{
    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");

    const char* wanted = std::getenv("PENUMBRA_VULKAN_DEVICE");
    std::vector<std::string> names;
    std::optional<PhysicalDeviceChoice> first;
    for (VkPhysicalDevice device : devices) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(device, &props);
        names.emplace_back(props.deviceName);
        const std::optional<std::uint32_t> family = graphicsQueueFamily(device);
        if (!family || props.apiVersion < VK_API_VERSION_1_1)
            continue;
        const PhysicalDeviceChoice choice{device, *family};
        if (wanted ? std::strstr(props.deviceName, wanted) != nullptr
                   : std::strstr(props.deviceName, "llvmpipe") != nullptr)
            return choice;
        if (!first)
            first = choice;
    }
    const std::string available = names.empty() ? "none" : fmt::format("'{}'", fmt::join(names, "', '"));
    if (wanted)
        throw rhi::Error(fmt::format("Vulkan: PENUMBRA_VULKAN_DEVICE='{}' matches no Vulkan 1.1 device with a "
                                     "graphics queue; devices: {}",
                                     wanted, available));
    if (!first)
        throw rhi::Error(fmt::format("Vulkan: no Vulkan 1.1 device with a graphics queue (devices: {}); "
                                     "install mesa-vulkan-drivers for lavapipe",
                                     available));
    return *first;
}

} // namespace penumbra::vulkan
