#pragma once

#include "penumbra/rhi/Backend.hpp"

#include <vector>

namespace penumbra {

// Every compiled backend's registration; defined in the file CMake generates from the
// penumbra_backend() calls of backends/CMakeLists.txt.
std::vector<rhi::BackendRegistration> compiledBackends();

} // namespace penumbra
