#pragma once

#include "penumbra/backends/Registry.hpp"
#include "penumbra/rhi/Device.hpp"

#include <memory>
#include <string_view>

namespace penumbra {

// Creates the device a desc asks for, through the backend that desc.backend names. A backend
// this build lacks is an rhi::UnsupportedError; a missing driver, display or extension is an
// rhi::Error (or rhi::UnsupportedError) whose message says what is missing.
std::unique_ptr<rhi::Device> createDevice(const rhi::DeviceDesc& desc);

// The same from a configuration name ("vulkan", "opengl-noclip-reversed", ...).
std::unique_ptr<rhi::Device> createDevice(std::string_view configuration);

} // namespace penumbra
