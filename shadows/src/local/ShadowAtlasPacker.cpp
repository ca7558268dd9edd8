#include "penumbra/shadows/ShadowAtlasPacker.hpp"

#include "QuadtreeAllocator.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <string>
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

void validatePackerInput(const ShadowAtlasPackerSettings& s)
{
    checkPowerOfTwo("atlasSize", s.atlasSize, 1, 1u << 16);
    checkPowerOfTwo("maxSize", s.maxSize, 1, s.atlasSize);
    checkPowerOfTwo("floorSize", s.floorSize, std::max(1u, s.atlasSize >> kMaxLevels), s.maxSize);
    if (!(s.hysteresis >= 0.0f && s.hysteresis <= 0.5f))
        throw rhi::Error(fmt::format("shadow atlas packer: hysteresis is {}, allowed 0 to 0.5 octaves", s.hysteresis));
}

void validatePackerInput(std::span<const ShadowTileRequest> requests)
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

// Lowers the given sizes until their area fits the atlas: the largest tile is halved first (ties: the lowest
// priority, then the highest id), down to the floor; with every light at the floor, the lowest priority loses its
// tiles (size 0).
void fitArea(std::span<const ShadowTileRequest> requests, std::vector<std::uint32_t>& sizes,
             const ShadowAtlasPackerSettings& s)
{
    const auto lower = [&](std::size_t a, std::size_t b) {
        return requests[a].priority != requests[b].priority ? requests[a].priority < requests[b].priority
                                                            : requests[a].lightId > requests[b].lightId;
    };
    std::vector<std::size_t> order(requests.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), lower);
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i)
        total += area(sizes[i], requests[i].tileCount);
    const std::uint64_t budget = area(s.atlasSize, 1);
    // Lights above the floor, the next to halve first: the largest size, then the lowest priority.
    const auto halveFirst = [&](std::size_t a, std::size_t b) {
        return sizes[a] != sizes[b] ? sizes[a] < sizes[b] : lower(b, a);
    };
    std::vector<std::size_t> heap;
    for (const std::size_t i : order)
        if (sizes[i] > s.floorSize)
            heap.push_back(i);
    std::make_heap(heap.begin(), heap.end(), halveFirst);
    std::size_t dropping = 0;
    while (total > budget) {
        if (!heap.empty()) {
            std::pop_heap(heap.begin(), heap.end(), halveFirst);
            const std::size_t i = heap.back();
            heap.pop_back();
            total -= area(sizes[i], requests[i].tileCount) - area(sizes[i] / 2, requests[i].tileCount);
            sizes[i] /= 2;
            if (sizes[i] > s.floorSize) {
                heap.push_back(i);
                std::push_heap(heap.begin(), heap.end(), halveFirst);
            }
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

using Block = QuadtreeAllocator::Block;

// Each light's tiles this frame (kept ones filled in before placeTiles) and last frame's (nullptr for a new light).
struct Tiles {
    std::vector<std::vector<Block>> blocks;
    std::vector<const std::vector<Block>*> previous;
    bool repacked;
};

// Places the tiles that lights do not keep: a light that shrinks takes the top-left quadrant of each old tile (its
// texels stay where they were), the rest go largest first into the smallest free blocks that hold them; where none
// is left, every tile is placed afresh, largest first, which fits whenever the area does.
void placeTiles(QuadtreeAllocator& allocator, std::span<const ShadowTileRequest> requests,
                const std::vector<std::uint32_t>& sizes, Tiles& tiles)
{
    for (std::size_t i = 0; i < sizes.size(); ++i)
        if (tiles.previous[i] && tiles.blocks[i].empty() && sizes[i] != 0 &&
            sizes[i] < allocator.blockSize(tiles.previous[i]->front()))
            for (const Block& old : *tiles.previous[i])
                if (const Block b = allocator.blockAt(allocator.offset(old), sizes[i]);
                    tiles.blocks[i].size() < requests[i].tileCount && allocator.allocateAt(b))
                    tiles.blocks[i].push_back(b);
    const std::vector<std::size_t> order = placementOrder(requests, sizes);
    for (const std::size_t i : order)
        while (tiles.blocks[i].size() < requests[i].tileCount && !tiles.repacked) {
            const std::optional<Block> b = allocator.allocate(sizes[i]);
            if (b)
                tiles.blocks[i].push_back(*b);
            else
                tiles.repacked = true;
        }
    if (!tiles.repacked)
        return;
    allocator.clear();
    for (const std::size_t i : order) {
        tiles.blocks[i].clear();
        for (std::uint32_t t = 0; t < requests[i].tileCount; ++t)
            tiles.blocks[i].push_back(allocator.allocate(sizes[i]).value());
    }
}

// Why a light got less than it wanted, or nullopt.
std::optional<std::string> note(const ShadowTileRequest& request, std::uint32_t wanted, std::uint32_t size,
                                std::uint64_t wantedArea, const ShadowAtlasPackerSettings& s)
{
    if (size == 0)
        return fmt::format("no shadow: the {0} x {0} local atlas has no room for its {1} tile(s) of the floor size "
                           "{2} x {2} with every light of higher priority at that size",
                           s.atlasSize, request.tileCount, s.floorSize);
    if (size < wanted)
        return fmt::format("shadow tile {0} x {0} instead of {1} x {1}: the tiles asked for need {2:.0f}% of the "
                           "{3} x {3} local atlas; larger tiles, then lower priorities, are lowered first",
                           size, wanted, 100.0 * double(wantedArea) / double(area(s.atlasSize, 1)), s.atlasSize);
    return std::nullopt;
}

void measureFreeSpace(const QuadtreeAllocator& allocator, std::uint32_t atlasSize, ShadowAtlasPack& result)
{
    const std::vector<std::set<std::uint32_t>>& free = allocator.freeBlocks();
    for (std::uint32_t level = 0; level < free.size(); ++level) {
        const std::uint32_t size = atlasSize >> level;
        result.freeTexels += area(size, static_cast<std::uint32_t>(free[level].size()));
        if (result.largestFreeTile == 0 && !free[level].empty())
            result.largestFreeTile = size;
    }
    if (result.freeTexels != 0)
        result.fragmentation =
            static_cast<float>(1.0 - double(area(result.largestFreeTile, 1)) / double(result.freeTexels));
}

} // namespace

ShadowAtlasPacker::ShadowAtlasPacker(const ShadowAtlasPackerSettings& settings) : settings_(settings)
{
    validatePackerInput(settings_);
    allocator_ = std::make_unique<QuadtreeAllocator>(settings_.atlasSize, settings_.floorSize);
}

ShadowAtlasPacker::ShadowAtlasPacker(const ShadowAtlasPackerSettings& settings, std::span<const PackedLight> previous)
    : ShadowAtlasPacker(settings)
{
    for (const PackedLight& light : previous) {
        if (light.size == 0 || !std::has_single_bit(light.size) || light.size < settings_.floorSize ||
            light.size > settings_.atlasSize)
            continue;
        Placed placed{light.lightId, light.wantedSize, light.size, {}};
        for (const glm::uvec2 offset : light.offsets) {
            const Block b = allocator_->blockAt(offset, light.size);
            if (offset.x % light.size != 0 || offset.y % light.size != 0 || offset.x >= settings_.atlasSize ||
                offset.y >= settings_.atlasSize || !allocator_->allocateAt(b))
                break;
            placed.blocks.push_back(b);
        }
        if (placed.blocks.size() == light.offsets.size())
            placed_.push_back(std::move(placed));
        else
            for (const Block& b : placed.blocks)
                allocator_->release(b);
    }
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
    validatePackerInput(requests);
    const std::size_t n = requests.size();
    std::unordered_map<std::uint32_t, std::size_t> requestOf;
    for (std::size_t i = 0; i < n; ++i)
        requestOf.emplace(requests[i].lightId, i);
    std::vector<std::uint32_t> wanted(n);
    std::vector<const Placed*> previous(n, nullptr);
    for (const Placed& p : placed_)
        if (const auto found = requestOf.find(p.lightId); found != requestOf.end())
            previous[found->second] = &p;
    for (std::size_t i = 0; i < n; ++i)
        wanted[i] = wantedSize(requests[i], settings_, previous[i] ? previous[i]->wantedSize : 0);
    std::vector<std::uint32_t> sizes = wanted;
    fitArea(requests, sizes, settings_);

    // Keep the tiles of lights whose size stays; free the others, then place those anew.
    Tiles tiles{std::vector<std::vector<Block>>(n), std::vector<const std::vector<Block>*>(n, nullptr), false};
    for (const Placed& p : placed_) {
        const auto found = requestOf.find(p.lightId);
        if (found != requestOf.end() && sizes[found->second] == p.size &&
            p.blocks.size() == requests[found->second].tileCount)
            tiles.blocks[found->second] = p.blocks;
        else
            for (const Block& b : p.blocks)
                allocator_->release(b);
    }
    for (std::size_t i = 0; i < n; ++i)
        tiles.previous[i] = previous[i] ? &previous[i]->blocks : nullptr;
    placeTiles(*allocator_, requests, sizes, tiles);

    ShadowAtlasPack result;
    result.repacked = tiles.repacked;
    std::uint64_t wantedArea = 0;
    for (std::size_t i = 0; i < n; ++i)
        wantedArea += area(wanted[i], requests[i].tileCount);
    std::vector<bool> moved(n);
    for (std::size_t i = 0; i < n; ++i)
        moved[i] = sizes[i] == 0 || !tiles.previous[i] || *tiles.previous[i] != tiles.blocks[i];
    placed_.clear(); // last frame's tiles, which tiles.previous points into, are done with
    for (std::size_t i = 0; i < n; ++i) {
        PackedLight light{requests[i].lightId, wanted[i], sizes[i], {}, moved[i]};
        for (const Block& b : tiles.blocks[i])
            light.offsets.push_back(allocator_->offset(b));
        result.usedTexels += area(sizes[i], requests[i].tileCount);
        if (std::optional<std::string> reason = note(requests[i], wanted[i], sizes[i], wantedArea, settings_))
            result.notes.push_back({light.lightId, std::move(*reason)});
        if (sizes[i] != 0)
            placed_.push_back({light.lightId, wanted[i], sizes[i], std::move(tiles.blocks[i])});
        result.lights.push_back(std::move(light));
    }
    measureFreeSpace(*allocator_, settings_.atlasSize, result);
    return result;
}

} // namespace penumbra::shadows
