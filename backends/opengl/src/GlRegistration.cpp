#include "penumbra/opengl/Registration.hpp"

#include "penumbra/opengl/OpenGLDevice.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace penumbra::opengl {
namespace {

void prepareOpenGLWindowHints(const rhi::DeviceDesc& desc)
{
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, desc.validation ? GLFW_TRUE : GLFW_FALSE);
    // Where the platform offers it (GLX/EGL robustness extensions; GLFW ignores the hint otherwise), a GPU reset
    // loses the context and glGetGraphicsResetStatus reports it (Capabilities::deviceLossReported).
    glfwWindowHint(GLFW_CONTEXT_ROBUSTNESS, GLFW_LOSE_CONTEXT_ON_RESET);
    // The RHI renders into its own framebuffers; the window only receives finished pictures.
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
}

rhi::NamedConfiguration configuration(const char* name, rhi::DepthRange range, bool reversedZ)
{
    return {name, {.backend = "opengl", .depthRange = range, .reversedZ = reversedZ}};
}

} // namespace

rhi::BackendRegistration registration()
{
    using rhi::DepthRange;
    return {.name = "opengl",
            .configurations = {configuration("opengl", DepthRange::ZeroToOne, false),
                               configuration("opengl-reversed", DepthRange::ZeroToOne, true),
                               configuration("opengl-noclip", DepthRange::MinusOneToOne, false),
                               configuration("opengl-noclip-reversed", DepthRange::MinusOneToOne, true)},
            .createDevice = [](const rhi::DeviceDesc& desc) { return createOpenGLDevice(desc); },
            .prepareWindowHints = prepareOpenGLWindowHints};
}

} // namespace penumbra::opengl
