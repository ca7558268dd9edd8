#pragma once

#include <CLI/CLI.hpp>

namespace penumbra::apps {

// `penumbra view`: the windowed viewer (apps/viewer).
void addViewCommand(CLI::App& app);

} // namespace penumbra::apps
