#include "GpuTesting.hpp"
#include "PrecisionScene.hpp"
#include "TestPattern.hpp"

#include "penumbra/rhi/Error.hpp"

#include <cmath>
#include <fmt/format.h>
#include <iostream>

namespace penumbra::testing {
namespace {

struct Rendered {
    std::string configuration;
    rhi::Image color;
    std::vector<float> viewDepth; // NaN where the far plane was kept
};

struct Patterns {
    std::vector<Rendered> rendered;
    std::vector<SkippedConfiguration> skipped;
};

// The test pattern through every configuration this build has, with validation on.
const Patterns& renderedPatterns()
{
    static const Patterns results = [] {
        Patterns out;
        for (const std::string& name : compiledConfigurations()) {
            std::unique_ptr<rhi::Device> device;
            try {
                device = createValidatedDevice(name);
            } catch (const rhi::UnsupportedError& e) {
                out.skipped.push_back({name, e.what()});
                continue;
            }
            pattern::PatternRenderer renderer(*device, {.width = 128, .height = 128});
            renderer.render(pattern::testPattern());
            Rendered r{name, renderer.color(), {}};
            const rhi::DepthImage depth = renderer.depth();
            for (float d : depth.depth)
                r.viewDepth.push_back(d == device->conventions().farDepth()
                                          ? NAN
                                          : device->conventions().viewDepth(renderer.projection(), d));
            savePicture(r.color, fmt::format("parity/{}", name));
            expectNoDebugMessages(*device);
            out.rendered.push_back(std::move(r));
        }
        return out;
    }();
    return results;
}

struct Difference {
    int maxAbs = 0;
    double psnr = INFINITY;
};

Difference compare(const rhi::Image& a, const rhi::Image& b)
{
    Difference d;
    double squared = 0.0;
    for (std::size_t i = 0; i < a.bytes.size(); ++i) {
        const int delta = std::abs(int(a.bytes[i]) - int(b.bytes[i]));
        d.maxAbs = std::max(d.maxAbs, delta);
        squared += double(delta) * delta;
    }
    if (squared > 0.0)
        d.psnr = 10.0 * std::log10(255.0 * 255.0 / (squared / double(a.bytes.size())));
    return d;
}

// PatternIsByteIdenticalEverywhere's judgement of one configuration's pattern against the first's.
::testing::AssertionResult sameBytes(const rhi::Image& reference, const rhi::Image& image)
{
    const Difference d = compare(reference, image);
    if (d.maxAbs == 0)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "max abs diff " << d.maxAbs << ", PSNR " << d.psnr << " dB";
}

TEST(ParityTest, EveryConfigurationIsRendered)
{
    std::vector<std::string> rendered;
    for (const Rendered& r : renderedPatterns().rendered)
        rendered.push_back(r.configuration);
    std::string reasons;
    for (const SkippedConfiguration& s : renderedPatterns().skipped)
        reasons += fmt::format("\n  {}: {}", s.name, s.reason);
    EXPECT_EQ(rendered, compiledConfigurations()) << "configurations this build has that the driver refused:" << reasons;
}

TEST(ParityTest, PatternIsByteIdenticalEverywhere)
{
    const auto& all = renderedPatterns().rendered;
    ASSERT_FALSE(all.empty());
    for (const Rendered& r : all) {
        const Difference d = compare(all.front().color, r.color);
        std::cout << fmt::format("[ parity ] pattern {} vs {}: max abs diff {}, PSNR {} dB\n", r.configuration,
                                 all.front().configuration, d.maxAbs, d.psnr);
        EXPECT_TRUE(sameBytes(all.front().color, r.color)) << r.configuration << " differs from " << all.front().configuration;
    }
    reportSkipped(renderedPatterns().skipped);
}

// The negative control of PatternIsByteIdenticalEverywhere: one pixel of a real rendered pattern changed by
// one level in one channel, the smallest fault there is, must be caught.
TEST(ParityTest, ChangedPatternPixelCatchesFault)
{
    const auto& all = renderedPatterns().rendered;
    ASSERT_FALSE(all.empty());
    rhi::Image changed = all.front().color;
    std::byte& green = changed.bytes[(std::size_t(changed.width) * (changed.height / 2) + changed.width / 2) * 4 + 1];
    green = std::byte(std::uint8_t(green) ^ 1u);
    ASSERT_TRUE(sameBytes(all.front().color, all.front().color));
    EXPECT_FALSE(sameBytes(all.front().color, changed));
}

TEST(ParityTest, LinearViewDepthAgreesEverywhere)
{
    const auto& all = renderedPatterns().rendered;
    ASSERT_FALSE(all.empty());
    for (const Rendered& r : all) {
        double worst = 0.0;
        int coverageMismatch = 0;
        for (std::size_t i = 0; i < r.viewDepth.size(); ++i) {
            const float a = all.front().viewDepth[i], b = r.viewDepth[i];
            if (std::isnan(a) != std::isnan(b))
                ++coverageMismatch;
            else if (!std::isnan(a))
                worst = std::max(worst, std::abs(double(a) - b) / a);
        }
        std::cout << fmt::format("[ parity ] view depth {} vs {}: max relative diff {:.3g}\n", r.configuration,
                                 all.front().configuration, worst);
        EXPECT_EQ(coverageMismatch, 0) << r.configuration;
        EXPECT_LT(worst, 1e-4) << r.configuration;
    }
    reportSkipped(renderedPatterns().skipped);
}

TEST(ParityTest, ReversedZBeatsTheStandardMappingAtDistance)
{
    int worstReversed = -1, bestStandard = -1;
    std::vector<SkippedConfiguration> skipped;
    for (const std::string& name : compiledConfigurations()) {
        std::unique_ptr<rhi::Device> device;
        try {
            device = createValidatedDevice(name);
        } catch (const rhi::UnsupportedError& e) {
            skipped.push_back({name, e.what()});
            continue;
        }
        const ZFighting z = countZFighting(*device);
        std::cout << fmt::format("[ z-fighting ] {}: {} of {} pixels\n", name, z.fighting, z.pixels);
        const bool precise = device->conventions().reversedZ() &&
                             device->conventions().depthRange() == rhi::DepthRange::ZeroToOne;
        int& slot = precise ? worstReversed : bestStandard;
        slot = slot < 0 ? z.fighting : (precise ? std::max(slot, z.fighting) : std::min(slot, z.fighting));
        expectNoDebugMessages(*device);
    }
    ASSERT_GE(worstReversed, 0);
    ASSERT_GE(bestStandard, 0);
    EXPECT_LT(worstReversed, bestStandard);
    reportSkipped(skipped);
}

} // namespace
} // namespace penumbra::testing
