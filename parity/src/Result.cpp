#include "penumbra/parity/Harness.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace penumbra::parity {

bool PairResult::pass() const
{
    return std::all_of(pictures.begin(), pictures.end(), [](const PictureComparison& c) { return c.pass(); });
}

const PictureComparison* PairResult::find(std::string_view picture) const
{
    for (const PictureComparison& c : pictures)
        if (c.picture == picture)
            return &c;
    return nullptr;
}

bool Result::pass() const
{
    return std::none_of(configurations.begin(), configurations.end(),
                        [](const ConfigurationRun& r) { return r.status == ConfigurationRun::Status::Failed; }) &&
           std::all_of(pairs.begin(), pairs.end(), [](const PairResult& p) { return p.pass(); });
}

std::string Result::pairName(const PairResult& pair) const
{
    return fmt::format("{} vs {}", configurations[pair.a].name(), configurations[pair.b].name());
}

std::vector<std::string> Result::failures() const
{
    std::vector<std::string> lines;
    for (const ConfigurationRun& run : configurations)
        if (run.status == ConfigurationRun::Status::Failed)
            lines.push_back(fmt::format("{}: {}", run.name(), run.message));
    for (const PairResult& pair : pairs)
        for (const PictureComparison& c : pair.pictures)
            for (const std::string& why : c.failures)
                lines.push_back(fmt::format("{}: {}: {}", pairName(pair), c.picture, why));
    return lines;
}

std::vector<std::string> Result::figures() const
{
    std::vector<std::string> lines;
    for (const PairResult& pair : pairs)
        for (const PictureComparison& c : pair.pictures)
            lines.push_back(
                fmt::format("{}: {}: {}{}", pairName(pair), c.picture, describe(c), c.pass() ? "" : " FAIL"));
    return lines;
}

std::string Result::summary() const
{
    std::vector<std::string> names;
    for (const PairResult& pair : pairs)
        for (const PictureComparison& c : pair.pictures)
            if (std::find(names.begin(), names.end(), c.picture) == names.end())
                names.push_back(c.picture);
    std::size_t rendered = 0;
    for (const ConfigurationRun& run : configurations)
        rendered += run.status == ConfigurationRun::Status::Rendered;
    std::string text = fmt::format("parity: {} of {} configurations rendered, {} pairs", rendered,
                                   configurations.size(), pairs.size());
    for (const std::string& name : names) {
        Figures worst;
        std::size_t rawPairs = 0, rawIdentical = 0;
        for (const PairResult& pair : pairs)
            if (const PictureComparison* c = pair.find(name)) {
                worst.maxDifference = std::max(worst.maxDifference, c->figures.maxDifference);
                worst.psnr = std::min(worst.psnr, c->figures.psnr);
                worst.differingPixels = std::max(worst.differingPixels, c->figures.differingPixels);
                worst.pixels = std::max(worst.pixels, c->figures.pixels);
                rawPairs += c->figures.rawDifferingTexels.has_value();
                rawIdentical += c->figures.rawDifferingTexels.value_or(1) == 0;
            }
        text += fmt::format("; {}: max diff {:.3g}, {}, at most {} of {} pixels differ", name, worst.maxDifference,
                            std::isinf(worst.psnr) ? "identical" : fmt::format("PSNR >= {:.1f} dB", worst.psnr),
                            worst.differingPixels, worst.pixels);
        if (rawPairs > 0)
            text +=
                fmt::format(", raw depth bit-identical in {}/{} pairs of equal conventions", rawIdentical, rawPairs);
    }
    return text + (pass() ? "; within the thresholds" : "; BEYOND the thresholds");
}

const ConfigurationRun& Result::configuration(std::string_view name) const
{
    for (const ConfigurationRun& run : configurations)
        if (run.name() == name)
            return run;
    std::string names;
    for (const ConfigurationRun& run : configurations)
        names += (names.empty() ? "" : ", ") + run.name();
    throw rhi::Error(fmt::format("parity: no configuration '{}' was run; these were: {}", name, names));
}

const PairResult* Result::pair(std::string_view a, std::string_view b) const
{
    for (const PairResult& p : pairs) {
        const std::string& pa = configurations[p.a].name();
        const std::string& pb = configurations[p.b].name();
        if ((pa == a && pb == b) || (pa == b && pb == a))
            return &p;
    }
    return nullptr;
}

} // namespace penumbra::parity
