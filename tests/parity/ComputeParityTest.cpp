// Compute results across configurations: every scene of ComputeScenes gives integer outputs (sums, counts, bytes),
// which must be bit-identical on every configuration; the histogram of a rendered picture also holds the two
// rasterizers to the same picture.
#include "../gpu/ComputeScenes.hpp"
#include "GpuTesting.hpp"

#include <map>
#include <numeric>

namespace penumbra::testing {
namespace {

// Everything one configuration computes, as one list of integers.
std::vector<std::uint32_t> computeEverything(rhi::Device& device)
{
    std::vector<std::uint32_t> values(1024);
    std::iota(values.begin(), values.end(), 1u);
    std::vector<std::uint32_t> all = prefixSum(device, values);
    const Histogram histogram = pictureHistogram(device);
    all.push_back(histogram.total);
    all.insert(all.end(), histogram.bins.begin(), histogram.bins.end());
    for (bool indirect : {false, true})
        for (std::uint8_t red : computedTriangle(device, indirect))
            all.push_back(red);
    all.push_back(indirectInvocations(device));
    const ImageSum image = storageImageSum(device);
    all.push_back(image.red);
    all.insert(all.end(), image.image.begin(), image.image.end());
    return all;
}

TEST(ComputeParity, IntegerResultsAreBitIdenticalEverywhere)
{
    std::map<std::string, std::vector<std::uint32_t>> results;
    reportSkipped(forEachConfiguration([&](rhi::Device& device, const std::string& configuration) {
        results[configuration] = computeEverything(device);
    }));
    ASSERT_FALSE(results.empty());
    const auto& [firstName, first] = *results.begin();
    for (const auto& [name, result] : results) {
        ASSERT_EQ(result.size(), first.size()) << name;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < result.size(); ++i)
            differing += result[i] != first[i];
        EXPECT_EQ(differing, 0u) << name << " against " << firstName << ": " << differing << " of " << result.size()
                                 << " values differ";
    }
}

} // namespace
} // namespace penumbra::testing
