#pragma once

#include "penumbra/parity/ImageDifference.hpp"
#include "ShadowScene.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::apps {

// What is left between the backends (a few triangle-edge texels and shadow-edge pixels, see README
// "Parity across backends" and tests/shadows_gpu/ShadowParityTest.cpp) stays far inside these coarse
// limits; a report fails only beyond them. Test patterns must be byte-identical.
struct ParityThresholds {
    double minLitPsnr = 50.0;             // dB over 255
    float maxLightDepthDifference = 2e-4f; // render::lightDepthFraction units: fractions of a tile's depth range
};

struct AtlasParity {
    std::string name;
    parity::FloatDifference lightDepth;       // comparable across conventions
    std::optional<bool> rawIdentical; // only where depth range and reversed-Z agree
    bool pass = true;
};

// Two configurations, by index into the compared pictures.
struct PairParity {
    std::size_t a = 0, b = 0;
    parity::ImageDifference lit;
    std::vector<AtlasParity> atlases;
    bool pass = true;
};

struct ParityReport {
    ParityThresholds thresholds;
    std::vector<PairParity> pairs;          // every pair of configurations
    std::vector<bool> patternIdentical;     // per configuration, against the first; empty without patterns
    bool pass = true;

    // One line: the worst figures over all pairs and whether they are within the thresholds.
    std::string summary(const std::vector<ShadowPictures>& pictures) const;
    // The pairs (and patterns) beyond the thresholds, "vulkan vs opengl: lit PSNR 41.2 dB < 50", one per line.
    std::string failures(const std::vector<ShadowPictures>& pictures) const;
};

// Compares every pair of configurations' lit images and atlases, and each test pattern with the first.
ParityReport compareParity(const std::vector<ShadowPictures>& pictures, const std::vector<rhi::Image>& patterns,
                           const ParityThresholds& thresholds = {});

// Writes into `folder`: parity.json (figures, thresholds, pass/fail), index.html (the pictures side
// by side with difference heat maps), diff/<a>-vs-<b>-lit.png and diff/<a>-vs-<b>-<atlas>.png.
// The pictures themselves are expected in <configuration>/ (writeShadowPictures).
void writeParityReport(const std::filesystem::path& folder, const ParityReport& report,
                       const std::vector<ShadowPictures>& pictures, const std::string& sceneName);

} // namespace penumbra::apps
