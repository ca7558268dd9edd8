#pragma once

#include "penumbra/rhi/Configuration.hpp"
#include "penumbra/rhi/Device.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace penumbra::rhi {

// What a backend tells the backends module about itself (penumbra::registeredBackends()).
struct BackendRegistration {
    // DeviceDesc::backend of its devices ("vulkan").
    std::string name;
    // The configurations it offers, each with `backend` set to `name`.
    std::vector<NamedConfiguration> configurations;
    // Creates a device; a missing driver or feature throws Error or UnsupportedError naming it.
    std::function<std::unique_ptr<Device>(const DeviceDesc&)> createDevice;
    // Sets the GLFW window hints a window for this backend needs; called after glfwInit and
    // before glfwCreateWindow.
    std::function<void(const DeviceDesc&)> prepareWindowHints;
};

} // namespace penumbra::rhi
