#pragma once

#include "penumbra/rhi/Device.hpp"

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace penumbra::apps {

// The RHI against hand-written raw API code, per configuration and call count: "<suite>/<configuration>/<path>/<n>"
// with path rhi, rhi-validated (the RHI's own validation layer on) and raw. Suites: draws (drawIndexed per cube),
// indirect (drawIndexedIndirect per cube) and dispatches (dispatches that each read the one before's writes).
class CallBench {
public:
    static const std::vector<std::string>& suites();

    // Registers the benchmarks of each of `suites` (those of suites()) on each configuration.
    CallBench(const std::vector<std::string>& suites, const std::vector<std::string>& configurations,
              const std::vector<std::uint32_t>& calls, double minTime);
    ~CallBench();

    // After benchmark::RunSpecifiedBenchmarks, given each benchmark's seconds per iteration: one table row per case.
    void printSummary(const std::map<std::string, double>& seconds) const;
    // The same figures: {"draws": [...], "indirect": [...], "dispatches": [...]}, one object per case.
    nlohmann::json toJson(const std::map<std::string, double>& seconds) const;

private:
    struct Case;
    struct Objects;
    std::vector<Case> cases_;
    std::unique_ptr<Objects> objects_;
};

} // namespace penumbra::apps
