#include "penumbra/backends/Registry.hpp"

#include "Registrations.hpp"
#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra {
namespace {

const std::vector<rhi::BackendRegistration>& backends()
{
    static const std::vector<rhi::BackendRegistration> registered = compiledBackends();
    return registered;
}

std::vector<rhi::NamedConfiguration> collectConfigurations()
{
    std::vector<rhi::NamedConfiguration> all;
    for (const rhi::BackendRegistration& b : backends())
        all.insert(all.end(), b.configurations.begin(), b.configurations.end());
    return all;
}

template <typename Items, typename Name>
std::string joinNames(const Items& items, Name name)
{
    std::string joined;
    for (const auto& item : items)
        joined += (joined.empty() ? "" : ", ") + std::string(name(item));
    return joined;
}

} // namespace

std::span<const rhi::BackendRegistration> registeredBackends() { return backends(); }

std::span<const rhi::NamedConfiguration> namedConfigurations()
{
    static const std::vector<rhi::NamedConfiguration> all = collectConfigurations();
    return all;
}

const rhi::BackendRegistration& findBackend(std::string_view name)
{
    for (const rhi::BackendRegistration& b : backends())
        if (b.name == name)
            return b;
    throw rhi::UnsupportedError(fmt::format("this build of Penumbra has no backend '{}'; it has: {}", name,
                                            joinNames(backends(), [](const auto& b) { return b.name; })));
}

rhi::DeviceDesc parseConfiguration(std::string_view name)
{
    for (const rhi::NamedConfiguration& c : namedConfigurations())
        if (c.name == name)
            return c.desc;
    throw rhi::Error(fmt::format("unknown configuration '{}'; valid configurations: {}", name,
                                 joinNames(namedConfigurations(), [](const auto& c) { return c.name; })));
}

std::string configurationName(const rhi::DeviceDesc& desc)
{
    for (const rhi::NamedConfiguration& c : namedConfigurations())
        if (c.desc.backend == desc.backend && c.desc.depthRange == desc.depthRange &&
            c.desc.reversedZ == desc.reversedZ)
            return c.name;
    return fmt::format("{}, depth {}{}", desc.backend,
                       desc.depthRange == rhi::DepthRange::ZeroToOne ? "[0, 1]" : "[-1, 1]",
                       desc.reversedZ ? ", reversed" : "");
}

} // namespace penumbra
