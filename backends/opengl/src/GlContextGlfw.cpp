#include "GlContext.hpp"

#include "penumbra/rhi/Error.hpp"

// GL comes from our own loader (GlFunctions), not from the header GLFW would include.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace penumbra::opengl {
namespace {

class GlfwWindowContext final : public PlatformContext {
public:
    explicit GlfwWindowContext(GLFWwindow* window) : window_(window)
    {
        if (glfwGetWindowAttrib(window_, GLFW_CLIENT_API) != GLFW_OPENGL_API)
            throw rhi::Error("OpenGL: the window has no OpenGL context; create it after penumbra::prepareWindowHints "
                             "with an OpenGL DeviceDesc");
    }

    void makeCurrent() override { glfwMakeContextCurrent(window_); }
    void release() override { glfwMakeContextCurrent(nullptr); }
    GlProc procAddress(const char* name) const override { return glfwGetProcAddress(name); }

private:
    GLFWwindow* window_;
};

} // namespace

std::unique_ptr<PlatformContext> createGlfwWindowContext(GLFWwindow* window)
{
    return std::make_unique<GlfwWindowContext>(window);
}

} // namespace penumbra::opengl
