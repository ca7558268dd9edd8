#include "penumbra/shadows/OccupancyRaster.hpp"

#include <algorithm>
#include <limits>

namespace penumbra::shadows {
namespace {

// Window positions per side of a block whose windows heaviest() bounds together: the samples crowd, so after the
// blocks with the highest bounds the rest bound below the best window found and are skipped (branch and bound).
constexpr int kBlock = 16;

// floor(a / b) for b > 0.
std::int64_t floorDiv(std::int64_t a, std::int64_t b)
{
    const std::int64_t q = a / b;
    return q * b > a ? q - 1 : q;
}

RasterWindowSums::Rect intersection(const RasterWindowSums::Rect& a, const RasterWindowSums::Rect& b)
{
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

} // namespace

RasterWindowSums::RasterWindowSums(const OccupancyRaster& raster) : nx_(raster.nx), ny_(raster.ny)
{
    const auto cells = static_cast<std::size_t>((nx_ + 1) * (ny_ + 1));
    mass_.assign(cells, 0);
    massX_.assign(cells, 0);
    massY_.assign(cells, 0);
    for (int y = 0; y < ny_; ++y) {
        std::int64_t row = 0, rowX = 0, rowY = 0;
        const auto above = static_cast<std::size_t>(y * (nx_ + 1));
        const auto here = above + static_cast<std::size_t>(nx_ + 1);
        for (int x = 0; x < nx_; ++x) {
            const std::int64_t m = raster.mass[static_cast<std::size_t>(y * nx_ + x)];
            row += m;
            rowX += m * x;
            rowY += m * y;
            const auto at = static_cast<std::size_t>(x + 1);
            mass_[here + at] = mass_[above + at] + row;
            massX_[here + at] = massX_[above + at] + rowX;
            massY_[here + at] = massY_[above + at] + rowY;
        }
    }
}

RasterWindowSums::Rect RasterWindowSums::clipped(int x, int y, int w, int h) const
{
    return {std::clamp(x, 0, nx_), std::clamp(y, 0, ny_), std::clamp(x + w, 0, nx_), std::clamp(y + h, 0, ny_)};
}

RasterWindowSums::Without::Without(const RasterWindowSums& sums, std::span<const RasterWindow> cleared) : sums_(sums)
{
    for (const RasterWindow& w : cleared) {
        const Rect r = sums.clipped(w.x, w.y, w.k, w.k);
        if (r.empty())
            continue;
        const std::size_t before = terms_.size();
        terms_.push_back({r, -1});
        for (std::size_t i = 0; i < before; ++i)
            if (const Rect both = intersection(terms_[i].rect, r); !both.empty())
                terms_.push_back({both, -terms_[i].sign});
    }
}

std::int64_t RasterWindowSums::Without::masked(const std::vector<std::int64_t>& table, const Rect& r,
                                               std::span<const Term> terms) const
{
    std::int64_t s = sums_.rectSum(table, r);
    for (const Term& term : terms)
        s += term.sign * sums_.rectSum(table, intersection(r, term.rect));
    return s;
}

std::int64_t RasterWindowSums::Without::sum(int x, int y, int k) const
{
    return masked(sums_.mass_, sums_.clipped(x, y, k, k), terms_);
}

glm::ivec2 RasterWindowSums::Without::centredCorner(int x, int y, int k) const
{
    const Rect r = sums_.clipped(x, y, k, k);
    const std::int64_t m = masked(sums_.mass_, r, terms_);
    if (m <= 0)
        return {x, y};
    // The mean cell centre is (sum of m (i + 1/2)) / m; the corner is floor(mean - k / 2 + 1/2), exactly.
    const auto corner = [&](const std::vector<std::int64_t>& moment) {
        return static_cast<int>(floorDiv(2 * masked(moment, r, terms_) + m - (k - 1) * m, 2 * m));
    };
    return {corner(sums_.massX_), corner(sums_.massY_)};
}

RasterWindow RasterWindowSums::Without::heaviest(int k) const
{
    const int columns = std::max(sums_.nx_, k) - k + 1, rows = std::max(sums_.ny_, k) - k + 1;
    struct Block {
        Rect positions; // window corners
        Rect reach; // the cells its windows cover
        std::int64_t bound = 0;
    };
    // Every window of a block lies in the block's reach, and masses are not negative, so the reach's mass outside the
    // cleared windows bounds theirs.
    std::vector<Block> blocks;
    for (int by = 0; by < rows; by += kBlock)
        for (int bx = 0; bx < columns; bx += kBlock) {
            const Rect positions{bx, by, std::min(bx + kBlock, columns), std::min(by + kBlock, rows)};
            const Rect reach = sums_.clipped(bx, by, positions.x1 - bx - 1 + k, positions.y1 - by - 1 + k);
            blocks.push_back({positions, reach, masked(sums_.mass_, reach, terms_)});
        }
    RasterWindow best{0, 0, k, -1};
    long long bestIndex = std::numeric_limits<long long>::max();
    std::vector<Term> near;
    const auto evaluate = [&](const Block& b) {
        near.clear();
        for (const Term& t : terms_)
            if (!intersection(t.rect, b.reach).empty())
                near.push_back(t);
        // Windows inside the raster with no cleared window near: four table entries each, no clamping.
        const bool plain = near.empty() && b.positions.x1 - 1 + k <= sums_.nx_ && b.positions.y1 - 1 + k <= sums_.ny_;
        const auto stride = static_cast<std::size_t>(sums_.nx_ + 1);
        for (int y = b.positions.y0; y < b.positions.y1; ++y) {
            const std::int64_t* top = sums_.mass_.data() + static_cast<std::size_t>(y) * stride;
            const std::int64_t* bottom = top + static_cast<std::size_t>(k) * stride;
            for (int x = b.positions.x0; x < b.positions.x1; ++x) {
                const std::int64_t s = plain ? bottom[x + k] - bottom[x] - top[x + k] + top[x]
                                             : masked(sums_.mass_, sums_.clipped(x, y, k, k), near);
                const long long index = static_cast<long long>(y) * columns + x;
                if (s > best.mass || (s == best.mass && index < bestIndex)) {
                    best = {x, y, k, s};
                    bestIndex = index;
                }
            }
        }
    };
    // The block with the highest bound first, for a high best; then every other block that may hold as much (the
    // best only grows, so none that could win is skipped, and ties go to the first window in row order whatever the
    // blocks' order).
    const auto first = std::max_element(blocks.begin(), blocks.end(),
                                        [](const Block& a, const Block& b) { return a.bound < b.bound; });
    evaluate(*first);
    for (auto b = blocks.begin(); b != blocks.end(); ++b)
        if (b != first && b->bound >= best.mass)
            evaluate(*b);
    return best;
}

} // namespace penumbra::shadows
