#include "penumbra/vulkan/Registration.hpp"

#include "penumbra/vulkan/VulkanDevice.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace penumbra::vulkan {
namespace {

void prepareVulkanWindowHints(const rhi::DeviceDesc&)
{
    glfwDefaultWindowHints();
    // The surface comes from glfwCreateWindowSurface; a GL context on the window would be in its way.
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
}

} // namespace

rhi::BackendRegistration registration()
{
    return {.name = "vulkan",
            .configurations = {{"vulkan", {.backend = "vulkan", .reversedZ = false}},
                               {"vulkan-reversed", {.backend = "vulkan", .reversedZ = true}}},
            .createDevice = createVulkanDevice,
            .prepareWindowHints = prepareVulkanWindowHints};
}

} // namespace penumbra::vulkan
