#pragma once

#include "penumbra/rhi/Configuration.hpp"

#include <cstdint>
#include <string>

struct GLFWwindow;

namespace penumbra::viewer {

// A GLFW window made for one device configuration (penumbra::prepareWindowHints); needs a live
// GlfwSession. Throws rhi::Error with GLFW's reason when no window can be made.
class ViewerWindow {
public:
    ViewerWindow(const rhi::DeviceDesc& desc, std::uint32_t width, std::uint32_t height, const std::string& title);
    ~ViewerWindow();
    ViewerWindow(const ViewerWindow&) = delete;
    ViewerWindow& operator=(const ViewerWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool shouldClose() const;

private:
    GLFWwindow* window_ = nullptr;
};

} // namespace penumbra::viewer
