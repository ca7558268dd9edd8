#include "RawDraws.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::apps {

std::unique_ptr<RawDraws> createRawDraws(rhi::Device& device, const DrawScene& scene)
{
    const std::string& backend = device.desc().backend;
    if (backend == "vulkan")
        return createRawVulkanDraws(device, scene);
    if (backend == "opengl")
        return createRawOpenGLDraws(device, scene);
    throw rhi::UnsupportedError(fmt::format("bench: no raw reference draws for the backend '{}'", backend));
}

} // namespace penumbra::apps
