#pragma once

#include "penumbra/parity/Harness.hpp"

#include <filesystem>
#include <string>

namespace penumbra::parity {

// Writes a result into `folder`, every file to a temporary name and renamed:
//   <configuration>/<picture>.png  each picture: colour as rendered (RGBA8 and RGBA8_SRGB), depth and
//                                  float as grey (white at the near plane, black at the far plane;
//                                  linear view depth and float values scaled to their range);
//   <configuration>/<picture>.exr  depth pictures' raw window depth, float pictures' values;
//   diff/<a>-vs-<b>-<picture>.png  difference heat maps: black where equal, then red, yellow, white
//                                  up to 8 steps (colour) or the picture's maxDifference (depth, float);
//   parity.json                    every figure, threshold and verdict, per configuration and pair;
//   index.html                     the pictures side by side with the heat maps and the figures.
// `title` heads the page ("mixed scene", "MyPass.Gradient").
void writeReport(const std::filesystem::path& folder, const Result& result, const std::string& title);

} // namespace penumbra::parity
