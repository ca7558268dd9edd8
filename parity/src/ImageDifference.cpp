#include "penumbra/parity/ImageDifference.hpp"

#include "penumbra/rhi/Error.hpp"

#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <limits>

namespace penumbra::parity {

ImageDifference compareImages(const rhi::Image& a, const rhi::Image& b)
{
    if (a.width != b.width || a.height != b.height || a.format != b.format)
        throw rhi::Error(fmt::format("cannot compare a {}x{} {} image with a {}x{} {} image", a.width, a.height,
                                     rhi::formatName(a.format), b.width, b.height, rhi::formatName(b.format)));
    ImageDifference d;
    const std::size_t texel = rhi::texelSize(a.format);
    double squared = 0.0;
    for (std::size_t p = 0; p < a.bytes.size() / texel; ++p) {
        bool differs = false;
        for (std::size_t c = 0; c < texel; ++c) {
            const int delta = std::abs(int(a.bytes[p * texel + c]) - int(b.bytes[p * texel + c]));
            d.maxAbs = std::max(d.maxAbs, delta);
            squared += double(delta) * delta;
            differs |= delta != 0;
        }
        d.differingPixels += differs;
    }
    const double mse = squared / double(a.bytes.size());
    d.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
    return d;
}

FloatDifference compareFloats(std::span<const float> a, std::span<const float> b)
{
    if (a.size() != b.size())
        throw rhi::Error(fmt::format("cannot compare {} values with {}", a.size(), b.size()));
    FloatDifference d;
    double squared = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const float delta = std::abs(a[i] - b[i]);
        d.maxAbs = std::max(d.maxAbs, delta);
        d.differingPixels += delta != 0.0f;
        squared += double(delta) * delta;
    }
    d.psnr = squared == 0.0 ? std::numeric_limits<double>::infinity()
                            : 10.0 * std::log10(1.0 / (squared / double(a.size())));
    return d;
}

} // namespace penumbra::parity
