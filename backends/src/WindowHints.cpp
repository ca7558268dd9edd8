#include "penumbra/backends/WindowHints.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace penumbra {

void prepareWindowHints(const rhi::DeviceDesc& desc)
{
    glfwDefaultWindowHints();
    if (desc.backend == rhi::Backend::Vulkan) {
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
        return;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, desc.validation ? GLFW_TRUE : GLFW_FALSE);
    // The RHI renders into its own framebuffers; the window only receives finished pictures.
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
}

} // namespace penumbra
