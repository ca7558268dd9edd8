#include "penumbra/backends/CreateDevice.hpp"

#include "penumbra/rhi/Error.hpp"

#if PENUMBRA_HAS_VULKAN
#include "penumbra/vulkan/VulkanDevice.hpp"
#endif
#if PENUMBRA_HAS_OPENGL
#include "penumbra/opengl/OpenGLDevice.hpp"
#endif

namespace penumbra {

std::unique_ptr<rhi::Device> createDevice(const rhi::DeviceDesc& desc)
{
    switch (desc.backend) {
    case rhi::Backend::Vulkan:
#if PENUMBRA_HAS_VULKAN
        return vulkan::createVulkanDevice(desc);
#else
        throw rhi::UnsupportedError("this build of Penumbra has no Vulkan backend (PENUMBRA_VULKAN=OFF)");
#endif
    case rhi::Backend::OpenGL:
#if PENUMBRA_HAS_OPENGL
        return opengl::createOpenGLDevice(desc);
#else
        throw rhi::UnsupportedError("this build of Penumbra has no OpenGL backend (PENUMBRA_OPENGL=OFF)");
#endif
    }
    throw rhi::Error("createDevice: unknown backend");
}

std::unique_ptr<rhi::Device> createDevice(std::string_view configuration)
{
    return createDevice(rhi::parseConfiguration(configuration));
}

} // namespace penumbra
