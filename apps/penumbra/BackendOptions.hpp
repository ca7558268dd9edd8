#pragma once

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

} // namespace penumbra::apps
