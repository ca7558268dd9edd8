#include "penumbra/rhi/ColorSpace.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace penumbra::rhi {
namespace {

std::uint8_t srgbCodeByFormula(double linear)
{
    return std::uint8_t(std::lround(std::clamp(linearToSrgb(std::clamp(linear, 0.0, 1.0)), 0.0, 1.0) * 255.0));
}

// A table lookup finds a value's code from buckets of this many over [0, 1]: under two codes a bucket.
constexpr std::size_t kSrgbCodeBuckets = 4096;
// Values this close (relatively) to a step take the formula: the formula's rounding errors (a few ulps of pow) can
// only move a step by far less, so elsewhere the table and the formula agree.
constexpr double kSrgbStepGuard = 1e-9;

struct SrgbCodeSteps {
    std::array<double, 257> first{}; // first[k]: the least double in [0, 1] whose code is k or more; first[256] = inf
    std::array<std::uint8_t, kSrgbCodeBuckets> bucketCode{}; // the code of each bucket's lowest value
};

const SrgbCodeSteps& srgbCodeSteps()
{
    static const SrgbCodeSteps steps = [] {
        SrgbCodeSteps made;
        // Non-negative doubles are ordered as their bit patterns: bisect those between 0 and 1 for each step.
        for (int code = 1; code < 256; ++code) {
            auto low = std::bit_cast<std::uint64_t>(0.0), high = std::bit_cast<std::uint64_t>(1.0);
            while (high - low > 1) {
                const std::uint64_t middle = low + (high - low) / 2;
                (srgbCodeByFormula(std::bit_cast<double>(middle)) >= code ? high : low) = middle;
            }
            made.first[std::size_t(code)] = std::bit_cast<double>(high);
        }
        made.first[256] = std::numeric_limits<double>::infinity();
        for (std::size_t bucket = 0, code = 0; bucket < kSrgbCodeBuckets; ++bucket) {
            while (double(bucket) / kSrgbCodeBuckets >= made.first[code + 1])
                ++code;
            made.bucketCode[bucket] = std::uint8_t(code);
        }
        return made;
    }();
    return steps;
}

} // namespace

double srgbToLinear(double encoded)
{
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double linear)
{
    return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

std::uint8_t linearToSrgbCode(double linear)
{
    if (!(linear > 0.0 && linear < 1.0))
        return srgbCodeByFormula(linear);
    const SrgbCodeSteps& steps = srgbCodeSteps();
    std::size_t code = steps.bucketCode[std::size_t(linear * kSrgbCodeBuckets)]; // exact: a power of two
    while (linear >= steps.first[code + 1])
        ++code;
    const double below = steps.first[code], above = steps.first[code + 1];
    if (linear - below <= below * kSrgbStepGuard || (code < 255 && above - linear <= above * kSrgbStepGuard))
        return srgbCodeByFormula(linear);
    return std::uint8_t(code);
}

} // namespace penumbra::rhi
