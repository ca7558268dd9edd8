#include "RawFrames.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::apps {
namespace {

[[noreturn]] void noRawReference(const rhi::Device& device)
{
    throw rhi::UnsupportedError(fmt::format("bench: no raw reference for the backend '{}'", device.desc().backend));
}

} // namespace

std::unique_ptr<RawFrame> createRawDraws(rhi::Device& device, const DrawScene& scene, DrawCall call)
{
    const std::string& backend = device.desc().backend;
    if (backend == "vulkan")
        return createRawVulkanDraws(device, scene, call);
    if (backend == "opengl")
        return createRawOpenGLDraws(device, scene, call);
    noRawReference(device);
}

std::unique_ptr<RawFrame> createRawDispatches(rhi::Device& device, const DispatchScene& scene)
{
    const std::string& backend = device.desc().backend;
    if (backend == "vulkan")
        return createRawVulkanDispatches(device, scene);
    if (backend == "opengl")
        return createRawOpenGLDispatches(device, scene);
    noRawReference(device);
}

} // namespace penumbra::apps
