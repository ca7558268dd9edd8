#pragma once

#include "ToolDevices.hpp"

#include "penumbra/rhi/Configuration.hpp"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace penumbra::apps {

// Validates a --configuration value against the named configurations, listing them on error.
CLI::Validator configurationValidator();

// Validates a --backend value: "all" or a configuration name ("vulkan" and "opengl" are both).
CLI::Validator backendValidator();

// The configurations --backend values name, in order, each once; "all" is every configuration.
std::vector<std::string> expandBackends(const std::vector<std::string>& backends);

// --validate: the Vulkan validation layer and GL debug output for this run. The tools run without them by default
// because they slow every call; PENUMBRA_VALIDATE=1 in the environment turns them on too, which is how the test
// suite keeps every run of the tools validating.
void addValidateFlag(CLI::App& command, bool& validate);

} // namespace penumbra::apps
