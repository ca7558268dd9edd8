#pragma once

// The parity harness: a render function of one's own through every configuration, each picture it
// returns compared between configurations, the figures judged against thresholds per picture.
//
//   parity::Options options;
//   options.thresholds["colour"] = {.maxDifference = 1, .maxDifferingPixels = 4};
//   const parity::Result result = parity::run([](rhi::Device& device, const rhi::NamedConfiguration&) {
//       MyPass pass(device);
//       return std::vector{parity::colorPicture("colour", pass.render()),
//                          parity::depthPicture("depth", pass.depth())};
//   }, options);
//   if (!result.pass()) { parity::writeReport("out/parity", result, "my pass"); ... result.failures() ... }
//
// Tests use penumbra/parity/GoogleTest.hpp (PENUMBRA_EXPECT_PARITY), which does the above.

#include "penumbra/parity/Comparison.hpp"
#include "penumbra/parity/Picture.hpp"
#include "penumbra/rhi/Configuration.hpp"
#include "penumbra/rhi/Device.hpp"

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::parity {

// Renders on `device` (fresh, validation on) for `configuration`; returns the pictures to compare.
// It may throw: that configuration is then reported failed with the message, the others compared.
using RenderFunction =
    std::function<std::vector<Picture>(rhi::Device& device, const rhi::NamedConfiguration& configuration)>;

// One configuration's run.
struct ConfigurationRun {
    // Whether the configuration rendered, was skipped by the driver, or failed.
    enum class Status {
        Rendered,
        Unsupported, // the driver refused the device (rhi::UnsupportedError): reported, not a failure
        Failed, // the device, the render function or validation failed: a failure
    };
    rhi::NamedConfiguration configuration;
    Status status = Status::Rendered;
    std::string message; // why it is unsupported or failed
    std::vector<Picture> pictures;

    // The configuration's name ("vulkan", ...).
    const std::string& name() const { return configuration.name; }
    // The configuration's depth conventions, for comparing depth across configurations.
    rhi::Conventions conventions() const { return {configuration.desc.depthRange, configuration.desc.reversedZ}; }
    // The picture called `name`; throws rhi::Error naming the pictures there are.
    const Picture& picture(std::string_view name) const;
};

// Which configurations are compared: every pair, or each with Options::reference.
enum class Pairing {
    EveryPair, // every configuration against every other
    AgainstReference, // every configuration against Options::reference
};

// How parity::run renders and compares: configurations, thresholds per picture and per pair, pairing.
struct Options {
    // The configurations by name ("vulkan", "opengl-noclip-reversed"); empty: every one this build
    // registered (penumbra::namedConfigurations()). An unknown name throws before anything renders.
    std::vector<std::string> configurations;
    Pairing pairing = Pairing::EveryPair;
    // AgainstReference: the configuration the others are compared with; empty: the first one.
    std::string reference;
    // Per picture name; a picture not named here has to be identical (Thresholds{}).
    std::map<std::string, Thresholds, std::less<>> thresholds;
    // When set, decides each pair's thresholds instead (`perPicture` is what `thresholds` says):
    // for bounds that depend on the pair, such as identical within one backend and a few pixels
    // across backends.
    std::function<Thresholds(const std::string& picture, const ConfigurationRun& a, const ConfigurationRun& b,
                             const Thresholds& perPicture)>
        pairThresholds;
    bool validate = true; // renderConfigurations' `validate`
};

// Two configurations, by index into Result::configurations, and each picture's comparison.
struct PairResult {
    std::size_t a = 0, b = 0;
    std::vector<PictureComparison> pictures;

    // Whether every picture of the pair met its thresholds.
    bool pass() const;
    // The comparison of one picture, or nullptr.
    const PictureComparison* find(std::string_view picture) const;
};

// Every configuration's run and every pair's comparison; failures(), figures() and summary() report them.
struct Result {
    std::vector<ConfigurationRun> configurations;
    std::vector<PairResult> pairs; // between the rendered configurations

    // Every pair within its thresholds and no configuration failed (unsupported ones do not fail).
    bool pass() const;
    // One line per threshold missed and per failed configuration: "vulkan vs opengl: colour: PSNR
    // 41.2 dB < 50 dB", "opengl: the render function threw: ...".
    std::vector<std::string> failures() const;
    // One line per pair and picture: "vulkan vs opengl: colour: max diff 1, PSNR 65.4 dB, ...".
    std::vector<std::string> figures() const;
    // One line: the worst figures per picture over all pairs, and whether they pass.
    std::string summary() const;
    // "vulkan vs opengl" for a pair.
    std::string pairName(const PairResult& pair) const;
    // The run of the configuration called `name`.
    const ConfigurationRun& configuration(std::string_view name) const;
    // The pair of two configurations by name (either order), or nullptr.
    const PairResult* pair(std::string_view a, std::string_view b) const;
};

// Every named configuration's run of `render`, in order: a fresh device with validation on (the API's
// validation layer / debug output; `validate` false leaves it off, as the tools do without --validate), the
// pictures, then any validation or debug message fails the configuration. Throws rhi::Error before
// rendering anything for an unknown configuration name, listing the known ones.
std::vector<ConfigurationRun> renderConfigurations(const RenderFunction& render,
                                                   const std::vector<std::string>& configurations = {},
                                                   bool validate = true);

// Compares the rendered runs as `options` say. Runs made by hand (pictures from files, say) work too.
Result compare(std::vector<ConfigurationRun> runs, const Options& options = {});

// renderConfigurations, then compare.
Result run(const RenderFunction& render, const Options& options = {});

} // namespace penumbra::parity
