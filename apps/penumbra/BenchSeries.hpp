#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace penumbra::apps {

// One series of per-frame figures of a benchmark: milliseconds, counts or ratios.
struct Series {
    std::vector<double> values;

    double median() const
    {
        if (values.empty())
            return 0.0;
        std::vector<double> sorted = values;
        std::sort(sorted.begin(), sorted.end());
        const std::size_t n = sorted.size();
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }
    double min() const { return values.empty() ? 0.0 : *std::min_element(values.begin(), values.end()); }
    double max() const { return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end()); }
};

} // namespace penumbra::apps
