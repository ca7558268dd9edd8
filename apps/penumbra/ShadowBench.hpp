#pragma once

#include "penumbra/rhi/Device.hpp"

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace penumbra::apps {

// The shadow test scene at 1280x720 with 4 cascades, a 2048 atlas and PCF 5x5, one benchmark per
// configuration ("shadows/<configuration>"); GPU pass times and caster draws become counters.
class ShadowBench {
public:
    explicit ShadowBench(const std::vector<std::string>& configurations, double minTime);
    ~ShadowBench();

    // After benchmark::RunSpecifiedBenchmarks: one table row per configuration.
    void printSummary() const;
    // The same figures, one object per configuration.
    nlohmann::json toJson() const;

private:
    struct Case;
    std::vector<std::unique_ptr<Case>> cases_;
};

} // namespace penumbra::apps
