#include "BoxPyramid.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::rhi {
namespace {

// A row halved along x with `filter`, Channels values a texel (a constant, so the channel loops unroll).
template <std::uint32_t Channels>
void halveRowOf(const AxisFilter& filter, const double* source, double* out)
{
    for (std::uint32_t d = 0; d < filter.to; ++d) {
        double* target = out + std::size_t(d) * Channels;
        const std::size_t first = filter.first[d], last = filter.first[d + 1];
        const double* texel = source + std::size_t(filter.taps[first].source) * Channels;
        for (std::uint32_t c = 0; c < Channels; ++c)
            target[c] = 0.0 + filter.taps[first].weight * texel[c];
        for (std::size_t t = first + 1; t < last; ++t) {
            texel = source + std::size_t(filter.taps[t].source) * Channels;
            for (std::uint32_t c = 0; c < Channels; ++c)
                target[c] += filter.taps[t].weight * texel[c];
        }
    }
}

} // namespace

AxisFilter axisFilter(std::uint32_t from)
{
    AxisFilter filter;
    filter.to = std::max(from / 2, 1u);
    const double scale = double(from) / double(filter.to); // source texels per destination texel
    for (std::uint32_t d = 0; d < filter.to; ++d) {
        filter.first.push_back(filter.taps.size());
        const double begin = d * scale, end = (d + 1) * scale;
        for (auto s = std::uint32_t(begin); s < from && s < end; ++s)
            filter.taps.push_back({s, (std::min(end, s + 1.0) - std::max(begin, double(s))) / scale});
    }
    filter.first.push_back(filter.taps.size());
    return filter;
}

BoxPyramid::BoxPyramid(std::uint32_t width, std::uint32_t height, std::uint32_t channels, std::uint32_t levels,
                       Level0Row level0Row, RowDone rowDone)
    : channels_(channels), level0Row_(std::move(level0Row)), rowDone_(std::move(rowDone))
{
    switch (channels) {
    case 1:
        halveRow_ = halveRowOf<1>;
        break;
    case 2:
        halveRow_ = halveRowOf<2>;
        break;
    case 4:
        halveRow_ = halveRowOf<4>;
        break;
    default:
        throw Error(fmt::format("BoxPyramid: {} channels is not 1, 2 or 4", channels));
    }
    levels_.push_back({.width = width, .height = height, .row = std::vector<double>(std::size_t(width) * channels)});
    for (std::uint32_t level = 1; level < levels; ++level) {
        const Level& above = levels_.back();
        Level next{.width = std::max(above.width / 2, 1u),
                   .height = std::max(above.height / 2, 1u),
                   .alongX = above.width > 1,
                   .alongY = above.height > 1};
        if (next.alongX)
            next.x = axisFilter(above.width);
        if (next.alongY)
            next.y = axisFilter(above.height);
        next.row.resize(std::size_t(next.width) * channels);
        next.xScratch.resize(next.row.size());
        levels_.push_back(std::move(next));
    }
}

void BoxPyramid::run()
{
    const auto last = std::uint32_t(levels_.size() - 1);
    for (std::uint32_t y = 0; last > 0 && y < levels_[last].height; ++y)
        row(last, y);
}

const double* BoxPyramid::row(std::uint32_t level, std::uint32_t y)
{
    Level& state = levels_[level];
    if (state.cached != std::int64_t(y)) {
        if (level == 0) {
            level0Row_(y, state.row.data());
        } else {
            computeRow(level, y);
            rowDone_(level, y, state.row.data());
        }
        state.cached = y;
    }
    return state.row.data();
}

void BoxPyramid::computeRow(std::uint32_t level, std::uint32_t y)
{
    Level& state = levels_[level];
    // The row of the level above halved along x, or that row itself where x stays.
    const auto xHalved = [&](std::uint32_t source, double* scratch) -> const double* {
        const double* above = row(level - 1, source);
        if (!state.alongX)
            return above;
        halveRow_(state.x, above, scratch);
        return scratch;
    };
    double* target = state.row.data();
    if (!state.alongY) {
        if (const double* halved = xHalved(0, target); halved != target)
            std::copy(halved, halved + state.row.size(), target);
        return;
    }
    const std::size_t first = state.y.first[y], last = state.y.first[y + 1];
    for (std::size_t t = first; t < last; ++t) {
        const double weight = state.y.taps[t].weight;
        const double* halved = xHalved(state.y.taps[t].source, state.xScratch.data());
        // The first tap adds to 0.0 as a zeroed sum would (0.0 + -0.0 is 0.0), without a pass to zero the row.
        if (t == first)
            for (std::size_t i = 0; i < state.row.size(); ++i)
                target[i] = 0.0 + weight * halved[i];
        else
            for (std::size_t i = 0; i < state.row.size(); ++i)
                target[i] += weight * halved[i];
    }
}

} // namespace penumbra::rhi
