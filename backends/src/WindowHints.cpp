#include "penumbra/backends/WindowHints.hpp"

#include "penumbra/backends/Registry.hpp"

namespace penumbra {

void prepareWindowHints(const rhi::DeviceDesc& desc) { findBackend(desc.backend).prepareWindowHints(desc); }

} // namespace penumbra
