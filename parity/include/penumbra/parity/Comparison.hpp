#pragma once

#include "penumbra/parity/Picture.hpp"

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::parity {

inline constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();
inline constexpr double kAnyDifference = std::numeric_limits<double>::infinity();

// What two configurations' pictures of one name may differ by. The defaults ask for identical
// pictures; every limit is loosened on its own.
struct Thresholds {
    // Largest |a - b| of one value: 8-bit steps for RGBA8 colour (bytes of any colour format), the
    // picture's DepthSpace units for depth (over texels drawn in both), the values' own for float.
    double maxDifference = 0.0;
    // Lowest PSNR, dB, peak 255 for colour and 1 for depth and float; identical pictures have
    // infinity, and 0 allows any.
    double minPsnr = 0.0;
    // Most pixels that may differ at all (any channel).
    std::size_t maxDifferingPixels = kAnyCount;
    // Depth: most texels drawn in one picture and background in the other.
    std::size_t maxCoverageMismatches = 0;
    // Depth: where both configurations share depth range and reversal the raw window depth has to
    // be bit-identical (the same rasteriser, the same numbers); across conventions only the
    // comparable values are judged.
    bool bitExactWhereConventionsAgree = true;
    // A judgement of one's own beyond these figures: the reason the pair fails, or nothing.
    std::function<std::optional<std::string>(const Picture& a, const rhi::Conventions& conventionsA, const Picture& b,
                                             const rhi::Conventions& conventionsB)>
        check;
};

// Byte identity for colour and float, bit-exact raw depth where conventions agree.
inline Thresholds identical() { return {}; }

// The figures of one comparison.
struct Figures {
    double maxDifference = 0.0;
    double psnr = std::numeric_limits<double>::infinity(); // dB; infinite when identical
    std::size_t differingPixels = 0; // depth: differing texels drawn in both, plus coverage mismatches
    std::size_t pixels = 0;
    std::size_t coverageMismatches = 0; // depth only
    std::optional<std::size_t> rawDifferingTexels; // depth where the conventions agree
};

// One picture of two configurations, judged against its thresholds.
struct PictureComparison {
    std::string picture;
    PictureKind kind = PictureKind::Color;
    Thresholds thresholds;
    Figures figures;
    // Each threshold missed ("PSNR 41.2 dB < 50 dB"), or why the pictures cannot be compared
    // ("sizes differ: RGBA8 64x64 and RGBA8 32x32"); empty when the pair passes.
    std::vector<std::string> failures;

    // Whether the picture met every threshold.
    bool pass() const { return failures.empty(); }
};

// Compares `a` (rendered under `conventionsA`) with `b`. Pictures of different kinds, sizes,
// formats or depth spaces are not compared: the comparison fails saying how they differ.
PictureComparison comparePictures(const Picture& a, const rhi::Conventions& conventionsA, const Picture& b,
                                  const rhi::Conventions& conventionsB, const Thresholds& thresholds = {});

// "max diff 1, PSNR 65.4 dB, 1 of 57600 pixels differ": the figures as the harness prints them.
std::string describe(const PictureComparison& comparison);

} // namespace penumbra::parity
