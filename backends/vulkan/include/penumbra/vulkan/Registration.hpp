#pragma once

#include "penumbra/rhi/Backend.hpp"

namespace penumbra::vulkan {

// The Vulkan backend as the backends module registers it: "vulkan" with the configurations
// vulkan and vulkan-reversed (depth [0, 1]), created by createVulkanDevice.
rhi::BackendRegistration registration();

} // namespace penumbra::vulkan
