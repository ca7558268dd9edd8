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

RasterWindowSums::Rect RasterWindowSums::intersection(const Rect& a, const Rect& b)
{
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// The union of the cleared windows as signed intersections (inclusion-exclusion): a rectangle's mass outside them is
// its own plus each term's sign times the mass of its intersection with the term.
std::vector<RasterWindowSums::Term> RasterWindowSums::terms(std::span<const RasterWindow> cleared) const
{
    std::vector<Term> out;
    for (const RasterWindow& w : cleared) {
        const Rect r = clipped(w.x, w.y, w.k, w.k);
        if (r.empty())
            continue;
        const std::size_t before = out.size();
        out.push_back({r, -1});
        for (std::size_t i = 0; i < before; ++i)
            if (const Rect both = intersection(out[i].rect, r); !both.empty())
                out.push_back({both, -out[i].sign});
    }
    return out;
}

std::int64_t RasterWindowSums::rectSum(const std::vector<std::int64_t>& t, const Rect& r) const
{
    if (r.empty())
        return 0;
    return table(t, r.x1, r.y1) - table(t, r.x0, r.y1) - table(t, r.x1, r.y0) + table(t, r.x0, r.y0);
}

std::int64_t RasterWindowSums::maskedSum(const std::vector<std::int64_t>& t, const Rect& r,
                                         std::span<const Term> terms) const
{
    std::int64_t s = rectSum(t, r);
    for (const Term& term : terms)
        s += term.sign * rectSum(t, intersection(r, term.rect));
    return s;
}

std::int64_t RasterWindowSums::sum(int x, int y, int k, std::span<const RasterWindow> cleared) const
{
    return maskedSum(mass_, clipped(x, y, k, k), terms(cleared));
}

glm::ivec2 RasterWindowSums::centredCorner(int x, int y, int k, std::span<const RasterWindow> cleared) const
{
    const std::vector<Term> t = terms(cleared);
    const Rect r = clipped(x, y, k, k);
    const std::int64_t m = maskedSum(mass_, r, t);
    if (m <= 0)
        return {x, y};
    // The mean cell centre is (sum of m (i + 1/2)) / m; the corner is floor(mean - k / 2 + 1/2), exactly.
    const auto corner = [&](const std::vector<std::int64_t>& moment) {
        return static_cast<int>(floorDiv(2 * maskedSum(moment, r, t) + m - (k - 1) * m, 2 * m));
    };
    return {corner(massX_), corner(massY_)};
}

RasterWindow RasterWindowSums::heaviest(int k, std::span<const RasterWindow> cleared) const
{
    const std::vector<Term> t = terms(cleared);
    const int columns = std::max(nx_, k) - k + 1, rows = std::max(ny_, k) - k + 1;
    struct Block {
        int x = 0;
        int y = 0;
        std::int64_t bound = 0;
    };
    // Every window of a block lies in the block's reach, and masses are not negative, so the reach's mass outside the
    // cleared windows bounds theirs.
    std::vector<Block> blocks;
    for (int by = 0; by < rows; by += kBlock)
        for (int bx = 0; bx < columns; bx += kBlock) {
            const int w = std::min(kBlock, columns - bx) - 1 + k, h = std::min(kBlock, rows - by) - 1 + k;
            blocks.push_back({bx, by, maskedSum(mass_, clipped(bx, by, w, h), t)});
        }
    std::stable_sort(blocks.begin(), blocks.end(), [](const Block& a, const Block& b) { return a.bound > b.bound; });
    RasterWindow best{0, 0, k, -1};
    long long bestIndex = std::numeric_limits<long long>::max();
    for (const Block& b : blocks) {
        if (b.bound < best.mass)
            break;
        for (int y = b.y; y < std::min(b.y + kBlock, rows); ++y)
            for (int x = b.x; x < std::min(b.x + kBlock, columns); ++x) {
                const std::int64_t s = maskedSum(mass_, clipped(x, y, k, k), t);
                const long long index = static_cast<long long>(y) * columns + x;
                if (s > best.mass || (s == best.mass && index < bestIndex)) {
                    best = {x, y, k, s};
                    bestIndex = index;
                }
            }
    }
    return best;
}

} // namespace penumbra::shadows
