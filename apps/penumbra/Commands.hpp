#pragma once

#include "penumbra/rhi/Image.hpp"

#include <CLI/CLI.hpp>
#include <string>

namespace penumbra::apps {

// Each adds one subcommand whose callback does the work; failures throw rhi::Error (or
// scene::SceneError for a scene that cannot be loaded).
void addPatternCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addParityCommand(CLI::App& app);
void addConfigurationsCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addTruthCommand(CLI::App& app);
void addBakeCommand(CLI::App& app);
void addSoakCommand(CLI::App& app);
void addSettingsCommand(CLI::App& app);

// The RHI test pattern through one configuration, size x size pixels, with the validation layer / debug output
// when `validate` is set.
rhi::Image renderPattern(const std::string& configuration, std::uint32_t size, bool validate);

} // namespace penumbra::apps
