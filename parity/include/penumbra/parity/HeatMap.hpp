#pragma once

#include "penumbra/rhi/Image.hpp"

#include <cstdint>
#include <span>

namespace penumbra::parity {

// Difference heat maps for parity reports, RGBA8, rows as the inputs: black where the pictures
// agree, then red, yellow and white as |a - b| grows to `fullScale` (and beyond, saturated), so
// single-step differences stay visible.

// Per pixel the largest difference of the colour channels, in 8-bit steps. Both RGBA8, same size.
rhi::Image differenceHeatMap(const rhi::Image& a, const rhi::Image& b, int fullScale);

// Two float images of width x height values.
rhi::Image differenceHeatMap(std::span<const float> a, std::span<const float> b, std::uint32_t width,
                             std::uint32_t height, float fullScale);

} // namespace penumbra::parity
