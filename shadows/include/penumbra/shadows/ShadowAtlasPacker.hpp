#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace penumbra::shadows {

// Places the local lights' shadow tiles of mixed sizes in one square atlas, frame after frame.
//
// Tiles are power-of-two squares in a quadtree (a two-dimensional buddy allocator), not shelves: power-of-two
// squares tile a power-of-two atlas with no waste (placed largest first, any set whose area fits, fits), freed
// quadrants merge back with their buddies, and a tile keeps its place by keeping its quadtree node, so placement is
// stable and cheap (a few set operations per tile). Shelves pack arbitrary rectangles but leave gaps at shelf ends
// that only a repack recovers.
//
// Each frame:
// - a request's size is clamped to [floorSize, maxSize] and rounded to a power of two; a light that had a tile keeps
//   its size while its request stays within `hysteresis` octaves beyond the rounding boundary (HDRP's and Godot's
//   caches need tiles that do not change with every small move of the camera);
// - when the tiles' area exceeds the atlas, the largest tiles are halved first, of lights of equal size the
//   lowest-priority light first, down to floorSize; only when every light is at the floor does the lowest-priority
//   light lose its shadow (never its light). Requests already grow with priority (localShadowRequest), so halving the
//   largest keeps their order while no light falls to the floor before the others have given up resolution;
// - a light whose size did not change keeps its tiles (PackedLight::moved false); a smaller one shrinks in place
//   (the top-left quadrant of its old tile); others take the smallest free block that holds them, largest first;
//   where the kept tiles leave no block large enough, every tile is placed afresh (ShadowAtlasPack::repacked).
struct ShadowAtlasPackerSettings {
    std::uint32_t atlasSize = 4096; // texels on a side, a power of two
    std::uint32_t floorSize = 64; // smallest tile before a light loses its shadow, a power of two
    std::uint32_t maxSize = 1024; // largest tile, a power of two from floorSize to atlasSize
    float hysteresis = 0.25f; // octaves, 0..0.5: how far past the rounding boundary a request moves a tile's size

    bool operator==(const ShadowAtlasPackerSettings&) const = default;
};

// One light's request for shadow tiles this frame.
struct ShadowTileRequest {
    std::uint32_t lightId = 0; // the same light from frame to frame has the same id; unique within a frame
    float size = 0.0f; // texels on a side the light asks for (localShadowRequest), any positive value
    float priority = 0.0f; // a higher priority keeps its resolution longer when space runs out
    std::uint32_t tileCount = 1; // tiles of one size: 1 for a spot light, 6 for a point light's cube faces
};

// Where the packer put one light's tiles, and at which size.
struct PackedLight {
    std::uint32_t lightId = 0; // ShadowTileRequest::lightId
    std::uint32_t wantedSize = 0; // the request clamped, rounded and held by the hysteresis
    std::uint32_t size = 0; // the size given, <= wantedSize; 0: no tile, the light casts no shadow this frame
    std::vector<glm::uvec2> offsets; // top-left texel of each tile (rows from the top, as rhi::Viewport); none if 0
    // The tiles differ from last frame's, or there are none (always so for a new light): cached maps are stale.
    bool moved = true;

    bool operator==(const PackedLight&) const = default;
};

// A light that lost resolution or its shadow, and why.
struct ShadowAtlasPackNote {
    std::uint32_t lightId = 0;
    std::string reason;
};

// One frame's packing: every light's tiles, the notes, and how full and fragmented the atlas is.
struct ShadowAtlasPack {
    std::vector<PackedLight> lights; // in request order
    std::vector<ShadowAtlasPackNote> notes; // in request order
    std::uint64_t usedTexels = 0;
    std::uint64_t freeTexels = 0;
    std::uint32_t largestFreeTile = 0; // texels on a side of the largest free square; 0 when full
    // The share of free texels outside the largest free square: pieces that a tile of the largest free size cannot
    // use (external fragmentation); 0 when the free space is one square or nothing.
    float fragmentation = 0.0f;
    bool repacked = false; // the kept tiles left no room, so every tile was placed afresh this frame
};

class QuadtreeAllocator;

// Places the local lights' shadow tiles in the atlas frame after frame, keeping each where it was while its request
// stays within the hysteresis band.
class ShadowAtlasPacker {
public:
    // Throws rhi::Error naming the setting and its allowed range.
    explicit ShadowAtlasPacker(const ShadowAtlasPackerSettings& settings);
    // A packer that holds `previous` (an earlier pack's lights, made with the same settings) where they were, as if it
    // had packed them: planning stays a function of its inputs and the last frame's allocation. Lights whose tiles no
    // longer fit where they were are left out (placed afresh by the next pack).
    ShadowAtlasPacker(const ShadowAtlasPackerSettings& settings, std::span<const PackedLight> previous);
    ~ShadowAtlasPacker();
    // Moves the packer with the tiles it keeps.
    ShadowAtlasPacker(ShadowAtlasPacker&&) noexcept;
    // Moves the packer with the tiles it keeps.
    ShadowAtlasPacker& operator=(ShadowAtlasPacker&&) noexcept;

    // The settings it was made with.
    const ShadowAtlasPackerSettings& settings() const { return settings_; }

    // Places this frame's tiles, keeping last frame's where it can. Throws rhi::Error for a request with a repeated
    // lightId, a size that is not a positive finite number, a priority that is not finite or a tileCount of 0;
    // nothing changes then.
    ShadowAtlasPack pack(std::span<const ShadowTileRequest> requests);
    // Forgets every tile: the next pack places all lights afresh.
    void clear();

private:
    struct Placed;
    ShadowAtlasPackerSettings settings_;
    std::unique_ptr<QuadtreeAllocator> allocator_;
    std::vector<Placed> placed_; // last frame's lights with a tile
};

} // namespace penumbra::shadows
