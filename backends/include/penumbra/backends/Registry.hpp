#pragma once

#include "penumbra/rhi/Backend.hpp"

#include <span>
#include <string>
#include <string_view>

namespace penumbra {

// The backends this build compiled, in the order backends/CMakeLists.txt registers them.
std::span<const rhi::BackendRegistration> registeredBackends();

// Every registered backend's configurations, backend by backend.
std::span<const rhi::NamedConfiguration> namedConfigurations();

// The registered backend called `name`; an unknown one throws UnsupportedError listing the compiled ones.
const rhi::BackendRegistration& findBackend(std::string_view name);

// The DeviceDesc of a named configuration; an unknown name throws an Error listing the valid ones.
rhi::DeviceDesc parseConfiguration(std::string_view name);

// The name of the registered configuration with a desc's backend, depth range and reversal
// ("opengl-noclip-reversed"); validation and window are ignored. A combination no backend
// registered gets a descriptive name ("vulkan, depth [-1, 1]").
std::string configurationName(const rhi::DeviceDesc& desc);

} // namespace penumbra
