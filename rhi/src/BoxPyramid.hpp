#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace penumbra::rhi {

// The box filter along one axis halved from `from` texels: destination texel d averages sources
// [first[d], first[d + 1]) of `taps`, weighted by the share of its area each covers, in ascending source order.
struct AxisFilter {
    struct Tap {
        std::uint32_t source = 0;
        double weight = 0.0;
    };
    std::uint32_t to = 0;
    std::vector<std::size_t> first;
    std::vector<Tap> taps;
};

AxisFilter axisFilter(std::uint32_t from);

// The levels of a mip chain, each the box filter of the level above (MipChain.hpp says how), computed a row at a
// time: a row of a level is computed once, from the rows of the level above that it covers, and those are asked for
// in ascending order, so each level holds one row of linear values and none is held whole (fresh whole levels of
// doubles were most of a large texture's chain time, in page faults: docs/notes/2026-12-06-large-texture-loading.md).
// Every sum starts at 0.0 and adds weight * value in ascending source order, x before y, so every value has the bits
// that filtering whole planes axis by axis gave.
class BoxPyramid {
public:
    // Writes row y of level 0 (width * channels linear values) to `out`.
    using Level0Row = std::function<void(std::uint32_t y, double* out)>;
    // Receives row y of `level` (1 or more): its width * channels values, valid until the call returns.
    using RowDone = std::function<void(std::uint32_t level, std::uint32_t y, const double* values)>;

    BoxPyramid(std::uint32_t width, std::uint32_t height, std::uint32_t channels, std::uint32_t levels,
               Level0Row level0Row, RowDone rowDone);

    // Computes every row of levels 1 to levels - 1, handing each to rowDone once, in ascending rows per level.
    void run();

private:
    struct Level {
        std::uint32_t width = 0, height = 0;
        bool alongX = false, alongY = false; // the axes halved from the level above
        AxisFilter x, y;
        std::vector<double> row; // the row last computed
        std::vector<double> xScratch; // a row of the level above halved along x
        std::int64_t cached = -1; // which row `row` holds
    };
    using HalveRow = void (*)(const AxisFilter& filter, const double* source, double* out);

    const double* row(std::uint32_t level, std::uint32_t y);
    void computeRow(std::uint32_t level, std::uint32_t y);

    std::uint32_t channels_;
    HalveRow halveRow_;
    Level0Row level0Row_;
    RowDone rowDone_;
    std::vector<Level> levels_;
};

} // namespace penumbra::rhi
