#pragma once

#include <CLI/CLI.hpp>

namespace penumbra::apps {

// Each adds one subcommand whose callback does the work; failures throw rhi::Error.
void addRenderCommand(CLI::App& app);
void addDemoCommand(CLI::App& app);
void addConfigurationsCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);

// Validates a --configuration value against the named configurations, listing them on error.
CLI::Validator configurationValidator();

} // namespace penumbra::apps
