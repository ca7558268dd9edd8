#include "QuadtreeAllocator.hpp"

#include <bit>

namespace penumbra::shadows {
namespace {

// Every other bit of `v` (bits 0, 2, 4, ...) packed together: one coordinate of a Morton index.
std::uint32_t compactBits(std::uint32_t v)
{
    v &= 0x55555555u;
    v = (v | (v >> 1)) & 0x33333333u;
    v = (v | (v >> 2)) & 0x0F0F0F0Fu;
    v = (v | (v >> 4)) & 0x00FF00FFu;
    v = (v | (v >> 8)) & 0x0000FFFFu;
    return v;
}

// The bits of `v` spread to the even positions: the inverse of compactBits.
std::uint32_t spreadBits(std::uint32_t v)
{
    v &= 0x0000FFFFu;
    v = (v | (v << 8)) & 0x00FF00FFu;
    v = (v | (v << 4)) & 0x0F0F0F0Fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
}

} // namespace

QuadtreeAllocator::QuadtreeAllocator(std::uint32_t atlasSize, std::uint32_t minBlockSize)
    : atlasSize_(atlasSize),
      free_(static_cast<std::size_t>(std::countr_zero(atlasSize) - std::countr_zero(minBlockSize)) + 1)
{
    clear();
}

void QuadtreeAllocator::clear()
{
    for (std::set<std::uint32_t>& level : free_)
        level.clear();
    free_[0].insert(0);
}

std::uint32_t QuadtreeAllocator::levelOf(std::uint32_t size) const
{
    return static_cast<std::uint32_t>(std::countr_zero(atlasSize_) - std::countr_zero(size));
}

glm::uvec2 QuadtreeAllocator::offset(Block block) const
{
    return glm::uvec2(compactBits(block.index), compactBits(block.index >> 1)) * blockSize(block);
}

QuadtreeAllocator::Block QuadtreeAllocator::blockAt(glm::uvec2 offset, std::uint32_t size) const
{
    const glm::uvec2 cell = offset / size;
    return {levelOf(size), spreadBits(cell.x) | (spreadBits(cell.y) << 1)};
}

std::optional<QuadtreeAllocator::Block> QuadtreeAllocator::allocate(std::uint32_t size)
{
    const std::uint32_t level = levelOf(size);
    // Best fit: the deepest level at or above the wanted one that has a free block.
    for (std::uint32_t j = level + 1; j-- > 0;) {
        if (free_[j].empty())
            continue;
        std::uint32_t index = *free_[j].begin();
        free_[j].erase(free_[j].begin());
        // Split down, keeping the top-left quadrant and freeing the other three at each level.
        for (std::uint32_t l = j; l < level; ++l) {
            index *= 4;
            free_[l + 1].insert({index + 1, index + 2, index + 3});
        }
        return Block{level, index};
    }
    return std::nullopt;
}

bool QuadtreeAllocator::allocateAt(Block block)
{
    for (std::uint32_t j = block.level + 1; j-- > 0;) {
        const std::uint32_t ancestor = block.index >> (2 * (block.level - j));
        if (free_[j].erase(ancestor) == 0)
            continue;
        // Split the free ancestor down the path to the block, freeing the three other quadrants at each level.
        for (std::uint32_t l = j; l < block.level; ++l) {
            const std::uint32_t child = block.index >> (2 * (block.level - l - 1));
            for (std::uint32_t sibling = child & ~3u; sibling < (child & ~3u) + 4; ++sibling)
                if (sibling != child)
                    free_[l + 1].insert(sibling);
        }
        return true;
    }
    return false;
}

void QuadtreeAllocator::release(Block block)
{
    std::uint32_t level = block.level;
    std::uint32_t index = block.index;
    free_[level].insert(index);
    // Merge four free buddies into their parent, as far up as they go.
    while (level > 0) {
        const std::uint32_t first = index & ~3u;
        std::set<std::uint32_t>& blocks = free_[level];
        if (!(blocks.contains(first) && blocks.contains(first + 1) && blocks.contains(first + 2) &&
              blocks.contains(first + 3)))
            break;
        blocks.erase(blocks.find(first), blocks.find(first + 3));
        blocks.erase(first + 3);
        index = first / 4;
        --level;
        free_[level].insert(index);
    }
}

} // namespace penumbra::shadows
