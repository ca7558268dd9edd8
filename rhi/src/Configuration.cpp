#include "penumbra/rhi/Configuration.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::rhi {

const std::array<NamedConfiguration, 6>& namedConfigurations()
{
    static const std::array<NamedConfiguration, 6> configurations = {{
        {"vulkan", {.backend = Backend::Vulkan, .reversedZ = false}},
        {"vulkan-reversed", {.backend = Backend::Vulkan, .reversedZ = true}},
        {"opengl", {.backend = Backend::OpenGL, .reversedZ = false}},
        {"opengl-reversed", {.backend = Backend::OpenGL, .reversedZ = true}},
        {"opengl-noclip", {.backend = Backend::OpenGL, .reversedZ = false, .clipControl = false}},
        {"opengl-noclip-reversed", {.backend = Backend::OpenGL, .reversedZ = true, .clipControl = false}},
    }};
    return configurations;
}

DeviceDesc parseConfiguration(std::string_view name)
{
    std::string valid;
    for (const NamedConfiguration& c : namedConfigurations()) {
        if (c.name == name)
            return c.desc;
        valid += (valid.empty() ? "" : ", ") + std::string(c.name);
    }
    throw Error(fmt::format("unknown configuration '{}'; valid configurations: {}", name, valid));
}

std::string configurationName(const DeviceDesc& desc)
{
    std::string name = desc.backend == Backend::Vulkan ? "vulkan" : "opengl";
    if (desc.backend == Backend::OpenGL && !desc.clipControl)
        name += "-noclip";
    if (desc.reversedZ)
        name += "-reversed";
    return name;
}

} // namespace penumbra::rhi
