#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace penumbra::apps {

// The lit pass of the shadow test scene at 1280x720 per configuration ("soft/<configuration>") and directional
// filter: PCF 5x5, Poisson 16, PCSS 16+16, 32+32 and 32+64 (blocker + filter samples), the four suns 3 degrees wide,
// a frame of each filter in turn; the summary gives each lit pass time over the same configuration's PCF 5x5,
// measured in the same run.
class SoftShadowBench {
public:
    SoftShadowBench(const std::vector<std::string>& configurations, double minTime);
    ~SoftShadowBench();

    void printSummary() const;
    nlohmann::json toJson() const;

private:
    struct Case;
    std::vector<std::unique_ptr<Case>> cases_;
};

} // namespace penumbra::apps
