#pragma once

#include "penumbra/rhi/Device.hpp"

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace penumbra::apps {

// Shadow passes at 1280x720 per configuration ("shadows/<scenario>/<configuration>"): the shadow test scene
// (4 cascades, 2048 atlas, PCF 5x5), 16 spot tiles, 2 point lights in 12 tiles and in cube maps; GPU pass
// times and caster draws become counters.
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
