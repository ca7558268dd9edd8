#include "ParityReport.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace penumbra::apps {

ParityReport compareParity(const std::vector<ShadowPictures>& pictures, const std::vector<rhi::Image>& patterns,
                           const ParityThresholds& thresholds)
{
    ParityReport report;
    report.thresholds = thresholds;
    for (std::size_t i = 0; i < pictures.size(); ++i) {
        for (std::size_t j = i + 1; j < pictures.size(); ++j) {
            const ShadowPictures& a = pictures[i];
            const ShadowPictures& b = pictures[j];
            PairParity pair{i, j, parity::compareImages(a.lit, b.lit), {}, true};
            pair.pass = pair.lit.psnr >= thresholds.minLitPsnr;
            for (const AtlasPictures& atlasA : a.atlases) {
                const AtlasPictures& atlasB = b.atlas(atlasA.name);
                AtlasParity atlas{atlasA.name, parity::compareFloats(atlasA.lightDepth, atlasB.lightDepth), std::nullopt, true};
                if (a.depthRange == b.depthRange && a.reversedZ == b.reversedZ)
                    atlas.rawIdentical = parity::compareFloats(atlasA.depth.depth, atlasB.depth.depth).differingPixels == 0;
                atlas.pass = atlas.lightDepth.maxAbs <= thresholds.maxLightDepthDifference;
                pair.pass = pair.pass && atlas.pass;
                pair.atlases.push_back(atlas);
            }
            report.pass = report.pass && pair.pass;
            report.pairs.push_back(std::move(pair));
        }
    }
    for (const rhi::Image& pattern : patterns) {
        report.patternIdentical.push_back(pattern.bytes == patterns.front().bytes);
        report.pass = report.pass && report.patternIdentical.back();
    }
    return report;
}

std::string ParityReport::summary(const std::vector<ShadowPictures>& pictures) const
{
    int litMax = 0;
    std::size_t litDiffering = 0;
    double litPsnr = std::numeric_limits<double>::infinity();
    float lightDepthMax = 0.0f;
    std::size_t rawPairs = 0, rawIdentical = 0;
    for (const PairParity& pair : pairs) {
        litMax = std::max(litMax, pair.lit.maxAbs);
        litDiffering = std::max(litDiffering, pair.lit.differingPixels);
        litPsnr = std::min(litPsnr, pair.lit.psnr);
        for (const AtlasParity& atlas : pair.atlases) {
            lightDepthMax = std::max(lightDepthMax, atlas.lightDepth.maxAbs);
            rawPairs += atlas.rawIdentical.has_value();
            rawIdentical += atlas.rawIdentical.value_or(false);
        }
    }
    const std::size_t pixels = pictures.empty() ? 0 : std::size_t(pictures.front().lit.width) * pictures.front().lit.height;
    const std::string psnr = std::isinf(litPsnr) ? "identical" : fmt::format("PSNR >= {:.1f} dB", litPsnr);
    return fmt::format("parity: {} configurations, {} pairs; lit: max diff {}, {}, at most {} of {} pixels differ; "
                       "atlas bit-identical in {}/{} pairs of equal conventions; light-depth max diff {:.3g}; {}",
                       pictures.size(), pairs.size(), litMax, psnr, litDiffering, pixels, rawIdentical, rawPairs,
                       lightDepthMax, pass ? "within the thresholds" : "BEYOND the thresholds");
}

std::string ParityReport::failures(const std::vector<ShadowPictures>& pictures) const
{
    std::string lines;
    for (const PairParity& pair : pairs) {
        const std::string names = fmt::format("{} vs {}", pictures[pair.a].configuration, pictures[pair.b].configuration);
        if (pair.lit.psnr < thresholds.minLitPsnr)
            lines += fmt::format("{}: lit PSNR {:.1f} dB < {} dB\n", names, pair.lit.psnr, thresholds.minLitPsnr);
        for (const AtlasParity& atlas : pair.atlases)
            if (!atlas.pass)
                lines += fmt::format("{}: {} atlas light-depth difference {:.3g} > {:.3g}\n", names, atlas.name,
                                     atlas.lightDepth.maxAbs, thresholds.maxLightDepthDifference);
    }
    for (std::size_t i = 0; i < patternIdentical.size(); ++i)
        if (!patternIdentical[i])
            lines += fmt::format("{}: test pattern differs from {}'s\n", pictures[i].configuration,
                                 pictures.front().configuration);
    return lines;
}

} // namespace penumbra::apps
