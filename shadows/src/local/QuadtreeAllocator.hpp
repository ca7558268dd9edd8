#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <optional>
#include <set>
#include <vector>

namespace penumbra::shadows {

// The buddy system (Knuth, The Art of Computer Programming vol. 1, 2.5 "Dynamic storage allocation", the buddy
// system) in two dimensions: a square power-of-two atlas is a quadtree whose level-L blocks are atlasSize >> L on a
// side. A block is split into its four quadrants to give a smaller one and four free quadrants merge back into their
// parent. Only the maximal free blocks are stored, per level, by their Morton index (x and y bits interleaved), so
// the first free block of a level is its top-left-most one.
class QuadtreeAllocator {
public:
    struct Block {
        std::uint32_t level = 0;
        std::uint32_t index = 0; // Morton index within its level
        friend bool operator==(const Block&, const Block&) = default;
    };

    // atlasSize and minBlockSize are powers of two, minBlockSize <= atlasSize (checked by the caller).
    QuadtreeAllocator(std::uint32_t atlasSize, std::uint32_t minBlockSize);

    // The smallest free block that holds a square of `size` texels (a power of two between the smallest block and the
    // atlas), split down to that size; nullopt when none is free.
    std::optional<Block> allocate(std::uint32_t size);
    // Takes a given block when it lies wholly in free space.
    bool allocateAt(Block block);
    void release(Block block);
    // Frees every block.
    void clear();

    std::uint32_t levelOf(std::uint32_t size) const;
    std::uint32_t blockSize(Block block) const { return atlasSize_ >> block.level; }
    // Top-left texel of a block, rows counted from the top.
    glm::uvec2 offset(Block block) const;
    // The block of `size` texels whose top-left texel is `offset` (aligned to size).
    Block blockAt(glm::uvec2 offset, std::uint32_t size) const;
    // The maximal free blocks of each level, by Morton index.
    const std::vector<std::set<std::uint32_t>>& freeBlocks() const { return free_; }

private:
    std::uint32_t atlasSize_;
    std::vector<std::set<std::uint32_t>> free_;
};

} // namespace penumbra::shadows
