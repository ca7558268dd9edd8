#include "penumbra/backends/CreateDevice.hpp"

namespace penumbra {

std::unique_ptr<rhi::Device> createDevice(const rhi::DeviceDesc& desc)
{
    return findBackend(desc.backend).createDevice(desc);
}

std::unique_ptr<rhi::Device> createDevice(std::string_view configuration)
{
    return createDevice(parseConfiguration(configuration));
}

} // namespace penumbra
