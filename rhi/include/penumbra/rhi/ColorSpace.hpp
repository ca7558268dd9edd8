#pragma once

namespace penumbra::rhi {

// The sRGB transfer function and its inverse (IEC 61966-2-1), on values in [0, 1]: what sampling
// Format::RGBA8_SRGB decodes and rendering to it encodes.
double srgbToLinear(double encoded);
double linearToSrgb(double linear);

} // namespace penumbra::rhi
