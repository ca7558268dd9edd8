#include "penumbra/parity/Comparison.hpp"

#include "penumbra/parity/ImageDifference.hpp"
#include "penumbra/rhi/Error.hpp"

#include <cmath>
#include <fmt/format.h>

namespace penumbra::parity {
namespace {

// Why two pictures cannot be compared value by value, or nothing.
std::optional<std::string> incompatibility(const Picture& a, const Picture& b)
{
    if (a.kind != b.kind)
        return fmt::format("kinds differ: {} and {}", describe(a), describe(b));
    if (a.width() != b.width() || a.height() != b.height())
        return fmt::format("sizes differ: {} and {}", describe(a), describe(b));
    if (a.kind == PictureKind::Color && a.color.format != b.color.format)
        return fmt::format("formats differ: {} and {}", describe(a), describe(b));
    if (a.kind == PictureKind::Depth && a.space != b.space)
        return fmt::format("depth spaces differ: {} and {}", describe(a), describe(b));
    return std::nullopt;
}

Figures colorFigures(const Picture& a, const Picture& b)
{
    const ImageDifference d = compareImages(a.color, b.color);
    return {.maxDifference = double(d.maxAbs),
            .psnr = d.psnr,
            .differingPixels = d.differingPixels,
            .pixels = std::size_t(a.width()) * a.height()};
}

// Depth and float: max |a - b| and PSNR (peak 1) over texels drawn in both; coverage apart.
Figures valueFigures(const Picture& a, const rhi::Conventions& conventionsA, const Picture& b,
                     const rhi::Conventions& conventionsB)
{
    const ComparableValues va = comparableValues(a, conventionsA);
    const ComparableValues vb = comparableValues(b, conventionsB);
    Figures f{.pixels = va.values.size()};
    double squared = 0.0;
    std::size_t compared = 0;
    for (std::size_t i = 0; i < va.values.size(); ++i) {
        if (va.drawn[i] != vb.drawn[i]) {
            ++f.coverageMismatches;
            ++f.differingPixels;
            continue;
        }
        const double delta = std::abs(double(va.values[i]) - double(vb.values[i]));
        ++compared;
        if (!(delta == 0.0)) { // NaN differs too
            f.maxDifference = std::max(f.maxDifference, std::isnan(delta) ? kAnyDifference : delta);
            ++f.differingPixels;
            squared += delta * delta;
        }
    }
    if (squared > 0.0 && compared > 0)
        f.psnr = 10.0 * std::log10(1.0 / (squared / double(compared)));
    if (a.kind == PictureKind::Depth && conventionsA.depthRange() == conventionsB.depthRange() &&
        conventionsA.reversedZ() == conventionsB.reversedZ())
        f.rawDifferingTexels = compareFloats(a.depth.depth, b.depth.depth).differingPixels;
    return f;
}

std::string psnrText(double psnr) { return std::isinf(psnr) ? "identical" : fmt::format("PSNR {:.1f} dB", psnr); }

std::vector<std::string> missed(const Figures& f, const Thresholds& t, PictureKind kind)
{
    std::vector<std::string> out;
    if (f.maxDifference > t.maxDifference)
        out.push_back(fmt::format("max difference {:.4g} > {:.4g}", f.maxDifference, t.maxDifference));
    if (f.psnr < t.minPsnr)
        out.push_back(fmt::format("PSNR {:.1f} dB < {} dB", f.psnr, t.minPsnr));
    if (f.differingPixels > t.maxDifferingPixels)
        out.push_back(fmt::format("{} of {} pixels differ > {}", f.differingPixels, f.pixels, t.maxDifferingPixels));
    if (kind == PictureKind::Depth && f.coverageMismatches > t.maxCoverageMismatches)
        out.push_back(fmt::format("{} texels drawn in one and background in the other > {}", f.coverageMismatches,
                                  t.maxCoverageMismatches));
    if (t.bitExactWhereConventionsAgree && f.rawDifferingTexels.value_or(0) > 0)
        out.push_back(fmt::format("{} texels of raw window depth differ under the same conventions (bit-exact "
                                  "required)",
                                  *f.rawDifferingTexels));
    return out;
}

} // namespace

PictureComparison comparePictures(const Picture& a, const rhi::Conventions& conventionsA, const Picture& b,
                                  const rhi::Conventions& conventionsB, const Thresholds& thresholds)
{
    PictureComparison c{a.name, a.kind, thresholds, {}, {}};
    if (const auto why = incompatibility(a, b)) {
        c.failures.push_back(*why);
        return c;
    }
    c.figures = a.kind == PictureKind::Color ? colorFigures(a, b) : valueFigures(a, conventionsA, b, conventionsB);
    c.failures = missed(c.figures, thresholds, a.kind);
    if (thresholds.check)
        if (const auto why = thresholds.check(a, conventionsA, b, conventionsB))
            c.failures.push_back(*why);
    return c;
}

std::string describe(const PictureComparison& c)
{
    if (c.figures.pixels == 0)
        return "not compared";
    std::string text = fmt::format("max diff {:.4g}, {}, {} of {} pixels differ", c.figures.maxDifference,
                                   psnrText(c.figures.psnr), c.figures.differingPixels, c.figures.pixels);
    if (c.kind == PictureKind::Depth)
        text += fmt::format(", {} coverage mismatches", c.figures.coverageMismatches);
    if (c.figures.rawDifferingTexels)
        text += *c.figures.rawDifferingTexels == 0
                    ? ", raw bit-identical"
                    : fmt::format(", raw: {} texels differ", *c.figures.rawDifferingTexels);
    return text;
}

} // namespace penumbra::parity
