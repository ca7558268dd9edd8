#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"
#include "penumbra/shadows/TileTexelBounds.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

inline constexpr std::uint32_t maxShadowCubes = 4;

// A static local map's filter and normal bias (StaticShadowUniforms::localTiles).
struct alignas(16) LocalShadowTile {
    float normalBias = 0.0f; // normal offset per unit distance from the light plane
    ShadowFilter shadowFilter = ShadowFilter::PCF2x2; // the light's
};

inline constexpr std::array kLocalShadowTileFields{
    PENUMBRA_SHADER_FIELD(LocalShadowTile, normalBias),
    PENUMBRA_SHADER_FIELD(LocalShadowTile, shadowFilter),
};
inline constexpr shaders::ShaderStruct kLocalShadowTileStruct{"LocalShadowTile", sizeof(LocalShadowTile),
                                                              kLocalShadowTileFields};

// A point light's shadow cube as the lit shader reads it (PointShadowMode::CubeMap).
struct alignas(16) LocalShadowCube {
    glm::vec2 depthRow{0.0f}; // window depth = (x * -z + y) / z at major-axis distance z
    float normalBias = 0.0f; // the receiver-side normal offset per unit distance, 0 where the caster side takes it
    float invFaceSize = 0.0f; // 1 / face size (texels)
    ShadowFilter shadowFilter = ShadowFilter::PCF2x2; // the light's
    float lightTexels = 0.0f; // the light's radius in texels at unit distance (the Poisson and PCSS filters)
    float nearPlane = 0.0f;
};

inline constexpr std::array kLocalShadowCubeFields{
    PENUMBRA_SHADER_FIELD(LocalShadowCube, depthRow),    PENUMBRA_SHADER_FIELD(LocalShadowCube, normalBias),
    PENUMBRA_SHADER_FIELD(LocalShadowCube, invFaceSize), PENUMBRA_SHADER_FIELD(LocalShadowCube, shadowFilter),
    PENUMBRA_SHADER_FIELD(LocalShadowCube, lightTexels), PENUMBRA_SHADER_FIELD(LocalShadowCube, nearPlane),
};
inline constexpr shaders::ShaderStruct kLocalShadowCubeStruct{"LocalShadowCube", sizeof(LocalShadowCube),
                                                              kLocalShadowCubeFields};

// One tile of the realtime local atlas as the lit shader reads it: an element of the storage block LocalShadowTiles
// (local_shadows.glsl), so the atlas holds as many tiles as it has room for (no uniform array bounds them).
struct alignas(16) LocalAtlasTileData {
    glm::mat4 worldToAtlas{1.0f}; // world -> (u, v, depth) x w (divide by w)
    TileTexelBounds bounds; // its first and last texel
    PerspectiveTileSoft soft; // for the Poisson and PCSS filters
    float normalBias = 0.0f; // normal offset per unit distance from the light plane
    ShadowFilter shadowFilter = ShadowFilter::PCF2x2; // the light's
};

inline constexpr std::array kLocalAtlasTileFields{
    PENUMBRA_SHADER_FIELD(LocalAtlasTileData, worldToAtlas),
    PENUMBRA_SHADER_STRUCT_FIELD(LocalAtlasTileData, bounds, kTileTexelBoundsStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(LocalAtlasTileData, soft, kPerspectiveTileSoftStruct),
    PENUMBRA_SHADER_FIELD(LocalAtlasTileData, normalBias),
    PENUMBRA_SHADER_FIELD(LocalAtlasTileData, shadowFilter),
};
inline constexpr shaders::ShaderStruct kLocalAtlasTileStruct{"LocalAtlasTileData", sizeof(LocalAtlasTileData),
                                                             kLocalAtlasTileFields};
static_assert(shaders::matchesLayout(kLocalAtlasTileStruct, shaders::BlockLayout::Std430, true));
// The storage block LocalShadowTiles: every tile of the atlas, as many as it holds.
inline constexpr std::array kLocalShadowTilesFields{
    shaders::runtimeStructArrayField<LocalAtlasTileData>("tiles", 0, kLocalAtlasTileStruct)};
inline constexpr shaders::ShaderStruct kLocalShadowTilesBlock{"LocalShadowTiles", 0, kLocalShadowTilesFields};
static_assert(shaders::matchesLayout(kLocalShadowTilesBlock, shaders::BlockLayout::Std430));

// The lit shader's spot and point shadow block LocalShadows (local_shadows.glsl), uploaded as is; the atlas tiles are
// in the storage block LocalShadowTiles (LocalAtlasTileData).
struct LocalShadowUniforms {
    std::array<LocalShadowCube, maxShadowCubes> cubes{};
    float atlasSize = 0.0f; // texels on a side
    ShadowFilter defaultFilter = ShadowFilter::PCF2x2; // of a light without its own
    PointShadowMode pointMode = PointShadowMode::Atlas;
    SoftShadowUniforms soft;
};

inline constexpr std::array kLocalShadowFields{
    PENUMBRA_SHADER_STRUCT_FIELD(LocalShadowUniforms, cubes, kLocalShadowCubeStruct),
    PENUMBRA_SHADER_FIELD(LocalShadowUniforms, atlasSize),
    PENUMBRA_SHADER_FIELD(LocalShadowUniforms, defaultFilter),
    PENUMBRA_SHADER_FIELD(LocalShadowUniforms, pointMode),
    PENUMBRA_SHADER_STRUCT_FIELD(LocalShadowUniforms, soft, kSoftShadowStruct),
};
// The block LocalShadows, read through the instance name `localShadows`.
inline constexpr shaders::ShaderStruct kLocalShadowBlock{"LocalShadows", sizeof(LocalShadowUniforms),
                                                         kLocalShadowFields};
static_assert(shaders::matchesLayout(kLocalShadowBlock, shaders::BlockLayout::Std140));

} // namespace penumbra::shadows
