#include "penumbra/parity/GoogleTest.hpp"

#include "penumbra/parity/Report.hpp"

#include <cstdlib>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace penumbra::parity::testing {
namespace {

const ::testing::TestInfo* runningTest() { return ::testing::UnitTest::GetInstance()->current_test_info(); }

// Prints the figures, adds the failures, writes the report when there are any, marks the skips.
Result judged(Result result, const char* file, int line)
{
    for (const std::string& figures : result.figures())
        fmt::print("[ parity   ] {}\n", figures);
    std::string report;
    if (!result.pass()) {
        const std::filesystem::path folder = reportFolder();
        const ::testing::TestInfo* test = runningTest();
        writeReport(folder, result, test ? fmt::format("{}.{}", test->test_suite_name(), test->name()) : "parity");
        report = fmt::format("\nreport: {}", (folder / "index.html").string());
        fmt::print("[ parity   ] report: {}\n", (folder / "index.html").string());
    }
    for (const ConfigurationRun& c : result.configurations)
        if (c.status == ConfigurationRun::Status::Failed)
            ADD_FAILURE_AT(file, line) << c.name() << " failed: " << c.message << report;
    for (const PairResult& pair : result.pairs) {
        if (pair.pass())
            continue;
        std::string why;
        for (const PictureComparison& c : pair.pictures)
            for (const std::string& failure : c.failures)
                why += fmt::format("\n  {}: {}", c.picture, failure);
        ADD_FAILURE_AT(file, line) << result.pairName(pair) << " beyond the parity thresholds:" << why << report;
    }
    std::string unsupported;
    for (const ConfigurationRun& c : result.configurations)
        if (c.status == ConfigurationRun::Status::Unsupported)
            unsupported += fmt::format("\n  {}: {}", c.name(), c.message);
    if (!unsupported.empty())
        [&] { GTEST_SKIP() << "configurations the driver does not support:" << unsupported; }();
    return result;
}

} // namespace

std::filesystem::path reportFolder()
{
    const char* root = std::getenv("PENUMBRA_TEST_OUTPUT");
    const std::filesystem::path folder = std::filesystem::path(root && *root ? root : "test-output") / "parity";
    if (const ::testing::TestInfo* test = runningTest())
        return folder / test->test_suite_name() / test->name();
    return folder / "outside-a-test";
}

Result expectParity(const RenderFunction& render, const Options& options, const char* file, int line)
{
    return judged(run(render, options), file, line);
}

Result expectParity(std::vector<ConfigurationRun> runs, const Options& options, const char* file, int line)
{
    return judged(compare(std::move(runs), options), file, line);
}

} // namespace penumbra::parity::testing
