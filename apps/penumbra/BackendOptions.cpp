#include "BackendOptions.hpp"

#include "ToolDevices.hpp"

#include "penumbra/backends/Registry.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::apps {
namespace {

std::string configurationNames()
{
    std::string names;
    for (const rhi::NamedConfiguration& c : penumbra::namedConfigurations())
        names += (names.empty() ? "" : ", ") + std::string(c.name);
    return names;
}

} // namespace

CLI::Validator configurationValidator()
{
    return CLI::Validator(
        [](std::string& name) {
            try {
                penumbra::parseConfiguration(name);
            } catch (const rhi::Error& e) {
                return std::string(e.what());
            }
            return std::string();
        },
        "CONFIGURATION");
}

CLI::Validator backendValidator()
{
    return CLI::Validator(
        [](std::string& name) {
            for (const rhi::NamedConfiguration& c : penumbra::namedConfigurations())
                if (name == c.name)
                    return std::string();
            if (name == "all")
                return std::string();
            return fmt::format("unknown backend '{}'; use all or one of: {}", name, configurationNames());
        },
        "BACKEND");
}

void addValidateFlag(CLI::App& command, bool& validate)
{
    command
        .add_flag("--validate", validate,
                  "Run with the Vulkan validation layer and OpenGL debug output; any message they report fails the run "
                  "(also PENUMBRA_VALIDATE=1)")
        ->envname("PENUMBRA_VALIDATE");
}

std::vector<std::string> expandBackends(const std::vector<std::string>& backends)
{
    std::vector<std::string> configurations;
    const auto add = [&](const std::string& name) {
        if (std::find(configurations.begin(), configurations.end(), name) == configurations.end())
            configurations.push_back(name);
    };
    for (const std::string& backend : backends) {
        if (backend != "all") {
            add(backend);
            continue;
        }
        for (const rhi::NamedConfiguration& c : penumbra::namedConfigurations())
            add(std::string(c.name));
    }
    return configurations;
}

} // namespace penumbra::apps
