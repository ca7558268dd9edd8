#pragma once

#include "penumbra/rhi/Configuration.hpp"

namespace penumbra {

// Sets the GLFW window hints a window for `desc`'s backend needs (its registration's
// prepareWindowHints: no client API for Vulkan; a 4.5 core context, a debug one with
// desc.validation, for OpenGL). Call it after glfwInit and before glfwCreateWindow; then pass the
// window in DeviceDesc::window.
void prepareWindowHints(const rhi::DeviceDesc& desc);

} // namespace penumbra
