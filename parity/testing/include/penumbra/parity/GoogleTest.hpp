#pragma once

// A parity test in a few lines (target penumbra::parity_testing):
//
//   TEST(MyPass, SameOnEveryConfiguration)
//   {
//       penumbra::parity::Options options;
//       options.thresholds["colour"] = {.maxDifference = 1, .maxDifferingPixels = 16};
//       PENUMBRA_EXPECT_PARITY(renderMyPass, options);
//   }
//
// It runs the harness (penumbra/parity/Harness.hpp) on every configuration (or options.configurations),
// prints each pair's figures, and adds one GoogleTest failure per failed configuration and per pair
// beyond its thresholds, naming them; on failure it writes the report (penumbra/parity/Report.hpp) into
// the test's output folder, reportFolder(), and names it. Configurations the driver does not support
// mark the test skipped, naming each and why, after the others were compared (failures still fail).

#include "penumbra/parity/Harness.hpp"

#include <filesystem>

namespace penumbra::parity::testing {

// $PENUMBRA_TEST_OUTPUT (else ./test-output) / parity / <test suite> / <test name>, of the running test.
std::filesystem::path reportFolder();

// What PENUMBRA_EXPECT_PARITY does; `file` and `line` place the failures. Returns the result for
// further checks of one's own.
Result expectParity(const RenderFunction& render, const Options& options, const char* file, int line);
// The same for runs rendered before (parity::renderConfigurations), so that several tests can judge
// one render: Options::configurations is not used.
Result expectParity(std::vector<ConfigurationRun> runs, const Options& options, const char* file, int line);

// Where PENUMBRA_EXPECT_PARITY was written, so that its options can be a braced list.
struct ExpectParityAt {
    const char* file;
    int line;

    // Renders through every configuration and adds a GoogleTest failure per failed configuration or pair.
    Result operator()(const RenderFunction& render, const Options& options = {}) const
    {
        return expectParity(render, options, file, line);
    }
    // Compares runs rendered once (parity::renderConfigurations) and adds the failures.
    Result operator()(std::vector<ConfigurationRun> runs, const Options& options = {}) const
    {
        return expectParity(std::move(runs), options, file, line);
    }
};

} // namespace penumbra::parity::testing

// PENUMBRA_EXPECT_PARITY(render) or PENUMBRA_EXPECT_PARITY(render, options), with a RenderFunction or
// the runs of one, options a parity::Options or a braced list of its fields
// ({.configurations = {"vulkan", "opengl"}}); returns the parity::Result.
#define PENUMBRA_EXPECT_PARITY(render, ...)                                                                            \
    ::penumbra::parity::testing::ExpectParityAt{__FILE__, __LINE__}((render)__VA_OPT__(, ) __VA_ARGS__)
