#pragma once

#include "penumbra/rhi/Image.hpp"

#include <cstddef>
#include <span>

namespace penumbra::parity {

// How far two pictures of equal size and format are apart, per 8-bit channel.
struct ImageDifference {
    int maxAbs = 0;
    std::size_t differingPixels = 0;
    double psnr = 0.0; // dB over 255; infinite when identical
};

// Throws rhi::Error when size or format differ.
ImageDifference compareImages(const rhi::Image& a, const rhi::Image& b);

// Two float images (depth, light depth) of equal size: max |a - b|, the pixels that differ at all,
// and the PSNR of values in [0, 1] against peak 1.
struct FloatDifference {
    float maxAbs = 0.0f;
    std::size_t differingPixels = 0;
    double psnr = 0.0; // dB; infinite when identical
};
// Largest difference, differing values and PSNR (peak 1) of two equally long float arrays.
FloatDifference compareFloats(std::span<const float> a, std::span<const float> b);

} // namespace penumbra::parity
