#include "GlfwSession.hpp"

#include "penumbra/rhi/Error.hpp"

#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <string>

namespace penumbra::viewer {
namespace {

std::string lastError;

void recordError(int code, const char* description)
{
    lastError = fmt::format("{} (GLFW error 0x{:x})", description ? description : "unknown", code);
}

} // namespace

const char* lastGlfwError()
{
    static std::string reported;
    reported = std::move(lastError);
    lastError.clear();
    return reported.c_str();
}

GlfwSession::GlfwSession()
{
    glfwSetErrorCallback(recordError);
    if (!glfwInit())
        throw rhi::Error(fmt::format("cannot open a window: GLFW: {}", lastGlfwError()));
}

GlfwSession::~GlfwSession() { glfwTerminate(); }

} // namespace penumbra::viewer
