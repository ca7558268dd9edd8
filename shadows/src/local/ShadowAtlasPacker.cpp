#include "penumbra/shadows/ShadowAtlasPacker.hpp"

#include "QuadtreeAllocator.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <fmt/format.h>
#include <unordered_map>

namespace penumbra::shadows {

struct ShadowAtlasPacker::Placed {
    std::uint32_t lightId = 0;
    std::uint32_t wantedSize = 0;
    std::uint32_t size = 0;
    std::vector<QuadtreeAllocator::Block> blocks;
};

namespace {

// Morton indices stay within 32 bits up to 15 levels below the whole atlas.
constexpr std::uint32_t kMaxLevels = 15;

void checkPowerOfTwo(const char* field, std::uint32_t value, std::uint32_t low, std::uint32_t high)
{
    if (!std::has_single_bit(value) || value < low || value > high)
        throw rhi::Error(fmt::format("shadow atlas packer: {} is {}, allowed a power of two from {} to {}", field,
                                     value, low, high));
}

void validate(const ShadowAtlasPackerSettings& s)
{
    checkPowerOfTwo("atlasSize", s.atlasSize, 1, 1u << 16);
    checkPowerOfTwo("maxSize", s.maxSize, 1, s.atlasSize);
    checkPowerOfTwo("floorSize", s.floorSize, std::max(1u, s.atlasSize >> kMaxLevels), s.maxSize);
    if (!(s.hysteresis >= 0.0f && s.hysteresis <= 0.5f))
        throw rhi::Error(fmt::format("shadow atlas packer: hysteresis is {}, allowed 0 to 0.5 octaves", s.hysteresis));
}

void validate(std::span<const ShadowTileRequest> requests)
{
    std::vector<std::uint32_t> ids;
    for (std::size_t i = 0; i < requests.size(); ++i) {
        const ShadowTileRequest& r = requests[i];
        if (!(std::isfinite(r.size) && r.size > 0.0f))
            throw rhi::Error(fmt::format("shadow atlas packer: request {} (light {}) asks for size {}, allowed a "
                                         "positive finite number of texels",
                                         i, r.lightId, r.size));
        if (!std::isfinite(r.priority))
            throw rhi::Error(fmt::format("shadow atlas packer: request {} (light {}) has priority {}, allowed a finite "
                                         "number",
                                         i, r.lightId, r.priority));
        if (r.tileCount == 0)
            throw rhi::Error(fmt::format("shadow atlas packer: request {} (light {}) asks for 0 tiles, allowed 1 or "
                                         "more",
                                         i, r.lightId));
        ids.push_back(r.lightId);
    }
    std::sort(ids.begin(), ids.end());
    if (const auto repeated = std::adjacent_find(ids.begin(), ids.end()); repeated != ids.end())
        throw rhi::Error(fmt::format("shadow atlas packer: light {} is requested twice in one frame", *repeated));
}

std::uint64_t area(std::uint32_t size, std::uint32_t tileCount) { return std::uint64_t(size) * size * tileCount; }

// The request clamped and rounded to the nearest power of two in octaves; a light keeps last frame's size while its
// request stays within 0.5 + hysteresis octaves of it.
std::uint32_t wantedSize(const ShadowTileRequest& request, const ShadowAtlasPackerSettings& s,
                         std::uint32_t previousWanted)
{
    const float octaves =
        std::log2(std::clamp(request.size, static_cast<float>(s.floorSize), static_cast<float>(s.maxSize)));
    if (previousWanted != 0 && std::abs(octaves - std::log2(static_cast<float>(previousWanted))) <= 0.5f + s.hysteresis)
        return previousWanted;
    return 1u << static_cast<std::uint32_t>(std::lround(octaves));
}

// Lowers the given sizes until their area fits the atlas: the lowest priority (ties: the highest id) is halved down
// to the floor first, then the next; with every light at the floor, the lowest priority loses its tiles (size 0).
void fitArea(std::span<const ShadowTileRequest> requests, std::vector<std::uint32_t>& sizes,
             const ShadowAtlasPackerSettings& s)
{
    std::vector<std::size_t> order(requests.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return requests[a].priority != requests[b].priority ? requests[a].priority < requests[b].priority
                                                            : requests[a].lightId > requests[b].lightId;
    });
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i)
        total += area(sizes[i], requests[i].tileCount);
    const std::uint64_t budget = area(s.atlasSize, 1);
    std::size_t halving = 0;
    std::size_t dropping = 0;
    while (total > budget) {
        while (halving < order.size() && sizes[order[halving]] <= s.floorSize)
            ++halving;
        if (halving < order.size()) {
            const std::size_t i = order[halving];
            total -= area(sizes[i], requests[i].tileCount) - area(sizes[i] / 2, requests[i].tileCount);
            sizes[i] /= 2;
            continue;
        }
        const std::size_t i = order[dropping++];
        total -= area(sizes[i], requests[i].tileCount);
        sizes[i] = 0;
    }
}

// Placement order of new tiles: largest first (which never fails while the area fits an empty atlas), then by
// priority and id so that equal inputs give equal atlases.
std::vector<std::size_t> placementOrder(std::span<const ShadowTileRequest> requests,
                                        const std::vector<std::uint32_t>& sizes)
{
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < sizes.size(); ++i)
        if (sizes[i] != 0)
            order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (sizes[a] != sizes[b])
            return sizes[a] > sizes[b];
        if (requests[a].priority != requests[b].priority)
            return requests[a].priority > requests[b].priority;
        return requests[a].lightId < requests[b].lightId;
    });
    return order;
}

} // namespace

ShadowAtlasPacker::ShadowAtlasPacker(const ShadowAtlasPackerSettings& settings) : settings_(settings)
{
    validate(settings_);
    allocator_ = std::make_unique<QuadtreeAllocator>(settings_.atlasSize, settings_.floorSize);
}

ShadowAtlasPacker::~ShadowAtlasPacker() = default;
ShadowAtlasPacker::ShadowAtlasPacker(ShadowAtlasPacker&&) noexcept = default;
ShadowAtlasPacker& ShadowAtlasPacker::operator=(ShadowAtlasPacker&&) noexcept = default;

void ShadowAtlasPacker::clear()
{
    allocator_->clear();
    placed_.clear();
}

ShadowAtlasPack ShadowAtlasPacker::pack(std::span<const ShadowTileRequest> requests)
{
    validate(requests);
    const std::size_t n = requests.size();
    std::unordered_map<std::uint32_t, std::size_t> requestOf;
    for (std::size_t i = 0; i < n; ++i)
        requestOf.emplace(requests[i].lightId, i);
    std::vector<const Placed*> previous(n, nullptr);
    for (const Placed& p : placed_)
        if (const auto found = requestOf.find(p.lightId); found != requestOf.end())
            previous[found->second] = &p;

    std::vector<std::uint32_t> wanted(n);
    for (std::size_t i = 0; i < n; ++i)
        wanted[i] = wantedSize(requests[i], settings_, previous[i] ? previous[i]->wantedSize : 0);
    std::vector<std::uint32_t> sizes = wanted;
    fitArea(requests, sizes, settings_);

    // Keep the tiles of lights whose size stays; free the others.
    std::vector<std::vector<QuadtreeAllocator::Block>> blocks(n);
    for (const Placed& p : placed_) {
        const auto found = requestOf.find(p.lightId);
        if (found != requestOf.end() && sizes[found->second] == p.size)
            blocks[found->second] = p.blocks;
        else
            for (const QuadtreeAllocator::Block& b : p.blocks)
                allocator_->release(b);
    }
    std::vector<bool> moved(n, true);
    for (std::size_t i = 0; i < n; ++i)
        moved[i] = blocks[i].empty();
    // A light that shrinks takes the top-left quadrant of each old tile: its texels stay where they were.
    for (std::size_t i = 0; i < n; ++i)
        if (previous[i] && sizes[i] != 0 && sizes[i] < previous[i]->size)
            for (const QuadtreeAllocator::Block& old : previous[i]->blocks)
                if (const QuadtreeAllocator::Block b = allocator_->blockAt(allocator_->offset(old), sizes[i]);
                    allocator_->allocateAt(b))
                    blocks[i].push_back(b);
    // The rest, largest first, into the smallest free blocks that hold them.
    ShadowAtlasPack result;
    for (const std::size_t i : placementOrder(requests, sizes)) {
        while (blocks[i].size() < requests[i].tileCount && !result.repacked) {
            const std::optional<QuadtreeAllocator::Block> b = allocator_->allocate(sizes[i]);
            if (b)
                blocks[i].push_back(*b);
            else
                result.repacked = true;
        }
    }
    if (result.repacked) {
        allocator_->clear();
        for (const std::size_t i : placementOrder(requests, sizes)) {
            blocks[i].clear();
            for (std::uint32_t t = 0; t < requests[i].tileCount; ++t)
                blocks[i].push_back(allocator_->allocate(sizes[i]).value());
            moved[i] = !previous[i] || previous[i]->blocks != blocks[i];
        }
    }

    std::uint64_t wantedArea = 0;
    for (std::size_t i = 0; i < n; ++i)
        wantedArea += area(wanted[i], requests[i].tileCount);
    placed_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        PackedLight light{requests[i].lightId, wanted[i], sizes[i], {}, sizes[i] == 0 || moved[i]};
        for (const QuadtreeAllocator::Block& b : blocks[i])
            light.offsets.push_back(allocator_->offset(b));
        result.usedTexels += area(sizes[i], requests[i].tileCount);
        if (sizes[i] == 0)
            result.notes.push_back(
                {light.lightId,
                 fmt::format("no shadow: the {0} x {0} local atlas has no room for its {1} tile(s) of the floor size "
                             "{2} x {2} with every light of higher priority at that size",
                             settings_.atlasSize, requests[i].tileCount, settings_.floorSize)});
        else if (sizes[i] < wanted[i])
            result.notes.push_back(
                {light.lightId,
                 fmt::format("shadow tile {0} x {0} instead of {1} x {1}: the tiles asked for need "
                             "{2:.0f}% of the {3} x {3} local atlas; lights of lower priority are "
                             "lowered first",
                             sizes[i], wanted[i], 100.0 * double(wantedArea) / double(area(settings_.atlasSize, 1)),
                             settings_.atlasSize)});
        if (sizes[i] != 0)
            placed_.push_back({light.lightId, wanted[i], sizes[i], std::move(blocks[i])});
        result.lights.push_back(std::move(light));
    }
    const std::vector<std::set<std::uint32_t>>& free = allocator_->freeBlocks();
    for (std::uint32_t level = 0; level < free.size(); ++level) {
        const std::uint32_t size = settings_.atlasSize >> level;
        result.freeTexels += area(size, static_cast<std::uint32_t>(free[level].size()));
        if (result.largestFreeTile == 0 && !free[level].empty())
            result.largestFreeTile = size;
    }
    if (result.freeTexels != 0)
        result.fragmentation =
            static_cast<float>(1.0 - double(area(result.largestFreeTile, 1)) / double(result.freeTexels));
    return result;
}

} // namespace penumbra::shadows
