#pragma once

#include <cstdint>

namespace penumbra::rhi {

// The sRGB transfer function and its inverse (IEC 61966-2-1), on values in [0, 1]: what sampling
// Format::RGBA8_SRGB decodes and rendering to it encodes.
double srgbToLinear(double encoded);
double linearToSrgb(double linear);

// The 8-bit sRGB code of a linear value, rounded to nearest: the code of
// std::lround(std::clamp(linearToSrgb(std::clamp(linear, 0.0, 1.0)), 0.0, 1.0) * 255.0) for every double, found in a
// table of the values where the code steps up rather than by a pow per value.
std::uint8_t linearToSrgbCode(double linear);

} // namespace penumbra::rhi
