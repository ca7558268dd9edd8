#pragma once

#include "penumbra/rhi/Window.hpp"

#include <array>
#include <string>
#include <string_view>

namespace penumbra::rhi {

enum class Backend { Vulkan, OpenGL };

// How an OpenGL device gets a context without a window.
enum class GlContextProvider { EglSurfaceless, OSMesa };

// What a device is created with. The six named configurations below are the ones every
// test, demo folder and command line uses; any other combination is also valid.
struct DeviceDesc {
    Backend backend = Backend::Vulkan;
    bool reversedZ = false;
    // OpenGL only: use glClipControl (depth [0, 1], upper-left origin). Off forces the
    // [-1, 1] depth path and the vertex-stage Y flip that drivers without clip control need.
    bool clipControl = true;
    GlContextProvider glContext = GlContextProvider::EglSurfaceless;
    // Vulkan validation layer / GL debug output. Every message is recorded (see
    // Device::debugMessages) and, with throwOnDebugMessage, raised as an Error at the next submit.
    bool validation = true;
    bool throwOnDebugMessage = false;
    // A window to present to (Device::createSwapchain); none for offscreen devices. With one, an
    // OpenGL device takes its context from the window instead of glContext.
    WindowDesc window;
};

struct NamedConfiguration {
    std::string_view name;
    DeviceDesc desc;
};

// vulkan, vulkan-reversed, opengl, opengl-reversed, opengl-noclip, opengl-noclip-reversed.
const std::array<NamedConfiguration, 6>& namedConfigurations();

// The DeviceDesc of a named configuration; an unknown name throws an Error listing the valid ones.
DeviceDesc parseConfiguration(std::string_view name);

// The name of a desc's configuration ("opengl-noclip-reversed"), ignoring validation, context provider and window.
std::string configurationName(const DeviceDesc& desc);

} // namespace penumbra::rhi
