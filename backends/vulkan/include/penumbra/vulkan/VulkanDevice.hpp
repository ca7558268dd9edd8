#pragma once

#include "penumbra/rhi/Device.hpp"

#include <memory>

namespace penumbra::vulkan {

// A Vulkan 1.1+ device (lavapipe by default). Throws rhi::Error naming what is missing
// when there is no loader, no driver or no validation layer asked for by desc.validation.
std::unique_ptr<rhi::Device> createVulkanDevice(const rhi::DeviceDesc& desc);

} // namespace penumbra::vulkan
