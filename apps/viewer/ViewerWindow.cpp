#include "ViewerWindow.hpp"

#include "GlfwSession.hpp"

#include "penumbra/backends/Registry.hpp"
#include "penumbra/backends/WindowHints.hpp"
#include "penumbra/rhi/Error.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <fmt/format.h>

namespace penumbra::viewer {

ViewerWindow::ViewerWindow(const rhi::DeviceDesc& desc, std::uint32_t width, std::uint32_t height,
                           const std::string& title)
{
    prepareWindowHints(desc);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_)
        throw rhi::Error(fmt::format("cannot open a {}x{} window for {}: GLFW: {}", width, height,
                                     penumbra::configurationName(desc), lastGlfwError()));
}

ViewerWindow::~ViewerWindow() { glfwDestroyWindow(window_); }

bool ViewerWindow::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }

} // namespace penumbra::viewer
