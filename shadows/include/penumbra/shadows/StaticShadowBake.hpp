#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::shadows {

// One light's static map as a bake keeps it: light-space depth along each tile's view axis (linearShadowDepth), so
// that any convention restores it; the tiles stacked from top to bottom, each `size` texels square, row 0 on top.
struct BakedShadowMap {
    LightKind kind = LightKind::Directional;
    std::uint32_t lightIndex = 0;
    std::string lightName;
    std::uint32_t size = 0;
    std::vector<ShadowFrustum> frusta; // per tile, as planned when baked
    std::uint64_t hash = 0; // of the light's views and the static casters in them (render::staticMapHash)
    std::vector<float> depth; // size x size x frusta.size()
};

// A bake: where it was made, the static objects, and every light's map.
struct StaticShadowBake {
    std::string configuration; // where it was baked (any configuration loads it)
    std::vector<std::string> objects; // the static casters' objects
    std::vector<BakedShadowMap> maps;
};

// The map's tiles read from its static atlas (as rhi::readDepth gives it), in light-space depth.
BakedShadowMap bakeShadowMap(const StaticShadowMap& map, const ShadowAtlasLayout& atlas, const rhi::DepthImage& depth,
                             const rhi::Conventions& conventions);

// Writes a baked map's tiles into `atlasDepth` (the whole static atlas, atlas.atlasSize() squared, row 0 on top) as
// this convention's window depth, at the tiles `map` plans.
void restoreShadowMap(const BakedShadowMap& baked, const StaticShadowMap& map, const ShadowAtlasLayout& atlas,
                      const rhi::Conventions& conventions, std::vector<float>& atlasDepth);

// DIR/manifest.json (format, version, configuration, objects, lights with name, kind, index, file, size, tiles, hash
// and frusta) and one OpenEXR file of 32-bit float depth per light (DIR/<kind>-<index>.exr), each written to a
// temporary name and renamed. Throws rhi::Error naming the file that cannot be written.
void writeStaticShadowBake(const std::filesystem::path& directory, const StaticShadowBake& bake);

// Throws rhi::Error naming the file and what is wrong: a missing or unreadable manifest or depth file, a field of the
// wrong type, a depth file whose size is not the manifest's.
StaticShadowBake readStaticShadowBake(const std::filesystem::path& directory);

// "directional", "spot", "point": the manifest's kind names.
std::string_view bakedKindName(LightKind kind);

} // namespace penumbra::shadows
