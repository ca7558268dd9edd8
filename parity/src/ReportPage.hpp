#pragma once

#include "penumbra/parity/Harness.hpp"

#include <set>
#include <string>

namespace penumbra::parity {

// index.html of a report: the figures table, then per pair and picture both pictures
// (<configuration>/<picture>.png) beside their heat map where `heatMaps` holds its path
// (diff/<a>-vs-<b>-<picture>.png).
std::string reportPage(const Result& result, const std::string& title, const std::set<std::string>& heatMaps);

} // namespace penumbra::parity
