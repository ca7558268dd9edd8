// Directional shadow attenuation: cascade selection, fades, normal offset and each light's filter over the
// atlas: tent-filtered PCF (penumbra::shadows::tentFilterTaps) or the Poisson and PCSS filters
// (soft_shadows.glsl). The uniform block is penumbra::shadows::DirectionalShadowUniforms.

#include "directional_shadows_block.glsl"

// Read with texelFetch (shadow_filter.glsl).
layout(binding = PENUMBRA_BINDING_DIRECTIONAL_ATLAS) uniform sampler2D shadowAtlas;

struct CascadeSelection {
    int index;      // cascadeCount when the point is beyond every cascade
    float blend;    // weight of `index` against index + 1 (soft blend), 1 elsewhere
    float strength; // distance and last-cascade fade
};

// saturate((1 - distance * scale) * fade): FadedShadowStrength of Catlike Coding's "Directional
// Shadows" tutorial (section "Shadow Distance").
float fadedShadowStrength(float distance, float scale, float fade)
{
    return clamp((1.0 - distance * scale) * fade, 0.0, 1.0);
}

// Depth fit's tiles hold the surfaces seen, not a region of space: the point's distance in texels inside the light's
// tile `tile`, less the filter's reach (cascade.normalBias over the texel size is the filter-sized
// texel diagonal, twice that leaves room for the normal offset); <= 0 outside. The C++ twin is
// penumbra::shadows::selectCascade.
float tileMargin(int tile, CascadeData cascade, vec3 position)
{
    const vec2 texel = transformPoint(shadows.worldToAtlas[tile], position).xy * shadows.atlasSize;
    const TileTexelBounds bounds = shadows.tileBounds[tile];
    const vec2 inside = min(texel - vec2(bounds.first), vec2(bounds.last) + 1.0 - texel);
    return min(inside.x, inside.y) - 2.0 * cascade.normalBias / cascade.texelWorldSize;
}

// Stable fit: the first cascade whose selection sphere holds the point, faded on squared distance. Close fit: the
// first whose far split the view depth has not reached, faded linearly on view depth (Unity's "Close Fit" bands,
// Catlike Coding, "Rendering 7: Shadows", section 1.7). Depth fit: the first whose tile holds the point (map-based
// selection: Microsoft, "Cascaded Shadow Maps", section "Map-Based Cascade Selection") among the tiles of shadow slot
// `slot`'s light (each light's tiles are fitted around its own footprint), faded over the cascadeFade of the tile's
// half size inside its edge; the other projections ignore `slot`. The C++ twin is penumbra::shadows::selectCascade.
CascadeSelection selectCascade(int slot, vec3 position, float viewDepth, float dither)
{
    CascadeSelection s;
    s.blend = 1.0;
    s.strength = fadedShadowStrength(viewDepth, shadows.fade.inverseMaxDistance, shadows.fade.inverseDistanceFade);
    const int count = shadows.cascadeCount;
    const bool close = shadows.cascadeProjection == PENUMBRA_PROJECTION_CLOSE;
    const bool mapped = shadows.cascadeProjection == PENUMBRA_PROJECTION_DEPTHFIT;
    int i = 0;
    for (; i < count; ++i) {
        const CascadeData cascade = shadows.cascades[i];
        const vec3 offset = position - cascade.selectionCentre;
        const float distanceSquared = dot(offset, offset);
        const int tile = shadows.lights[max(slot, 0)].firstTile + i;
        const float margin = mapped ? tileMargin(tile, cascade, position) : 0.0;
        const float halfTexels = 0.5 * float(shadows.tileBounds[tile].last.x - shadows.tileBounds[tile].first.x + 1);
        if (mapped ? margin > 0.0
                   : (close ? viewDepth < cascade.farDepth : distanceSquared < cascade.selectionRadiusSquared)) {
            const float fade =
                mapped ? fadedShadowStrength(halfTexels - margin, 1.0 / halfTexels,
                                             shadows.fade.inverseDepthCascadeFade)
                : close
                    ? fadedShadowStrength(viewDepth, 1.0 / cascade.farDepth, shadows.fade.inverseDepthCascadeFade)
                    : fadedShadowStrength(distanceSquared, cascade.fadeScale, shadows.fade.inverseSphereCascadeFade);
            if (i == count - 1)
                s.strength *= fade;
            else
                s.blend = fade;
            break;
        }
    }
    if (i == count)
        s.strength = 0.0;
    else if (shadows.cascadeBlend == PENUMBRA_BLEND_DITHER && s.blend < dither)
        i += 1;
    if (shadows.cascadeBlend != PENUMBRA_BLEND_SOFT)
        s.blend = 1.0;
    s.index = i;
    return s;
}

// Light slot `slot`'s selection where `first` is slot 0's: depth fit selects in each light's own tiles, the other
// projections the same cascade for every light.
CascadeSelection selectLightCascade(CascadeSelection first, int slot, vec3 position, float viewDepth, float dither)
{
    if (slot <= 0 || shadows.cascadeProjection != PENUMBRA_PROJECTION_DEPTHFIT)
        return first;
    return selectCascade(slot, position, viewDepth, dither);
}

// Tile `bounds` of a directional depth atlas filtered at atlas position (u, v, depth) by `filterIndex`: the
// tent filters, or the Poisson and PCSS filters with the tile's soft data, the light's tan of half its angular diameter and the world size of a tile texel. `toAtlas` turns the
// receiver's screen derivatives into atlas units. The realtime cascades and the static maps (static_shadows.glsl)
// both filter through it.
float filterDirectionalTile(sampler2D atlas, vec3 atlasPosition, float atlasSize, TileTexelBounds bounds,
                            int filterIndex, mat3 toAtlas, DirectionalTileSoft tileSoft, float tanHalfAngle,
                            float texelWorld)
{
#if PENUMBRA_SOFT_FILTERS
    if (filterIndex < PENUMBRA_FILTER_FIRST_POISSON_DISK)
#endif
        return filterShadowTile(atlas, atlasPosition, atlasSize, filterIndex, bounds.first, bounds.last);
#if PENUMBRA_SOFT_FILTERS
    const SoftTile t =
        softTile(atlasPosition, toAtlas * receiverDx, toAtlas * receiverDy, atlasSize, bounds.first, bounds.last,
                 tileSoft.lightTexelAnchor, shadows.soft);
    return directionalSoftShadow(atlas, t, filterIndex, shadows.soft, tileSoft.depthRow, tanHalfAngle, texelWorld);
#endif
}

// The directional atlas's tile `tile` filtered at atlas position (u, v, depth) by light `slot`'s filter.
float filterDirectionalShadow(vec3 atlasPosition, int tile, int cascade, int slot)
{
    return filterDirectionalTile(shadowAtlas, atlasPosition, shadows.atlasSize, shadows.tileBounds[tile],
                                 shadows.lights[slot].shadowFilter, mat3(shadows.worldToAtlas[tile]), shadows.tileSoft[tile],
                                 shadows.lights[slot].tanHalfAngle, shadows.cascades[cascade].texelWorldSize);
}

// The receiver moved by its normal offset over the cascade's filter-sized texel diagonal (scaled to the light's
// filter), then filtered.
float sampleCascade(int tile, int cascade, int slot, vec3 position, vec3 normal, vec3 towardsLight, float normalBias)
{
    precise vec3 biased = position + receiverNormalOffset(normal, towardsLight,
                                                          normalBias * shadows.cascades[cascade].normalBias *
                                                              shadows.lights[slot].filterBiasScale);
    return filterDirectionalShadow(transformPoint(shadows.worldToAtlas[tile], biased).xyz, tile, cascade, slot);
}

// The filtered shadow map alone, before any strength or fade (1 = lit): what ground truth compares.
// `normal` is the receiver's geometric normal (either side), `towardsLight` the unit direction to the light.
float directionalShadowVisibility(int slot, CascadeSelection s, vec3 position, vec3 normal, vec3 towardsLight)
{
    const DirectionalShadowLight light = shadows.lights[slot];
    const int tile = light.firstTile + s.index;
    // One call site for both cascades of a soft blend: the compilers inline every call, and the soft filters' loops
    // are long.
    float shadow = 0.0;
    const int cascades = s.blend < 1.0 ? 2 : 1;
    for (int k = 0; k < cascades; ++k) {
        const float weight = cascades == 1 ? 1.0 : (k == 0 ? s.blend : 1.0 - s.blend);
        shadow += weight * sampleCascade(tile + k, s.index + k, slot, position, normal, towardsLight, light.normalBias);
    }
    return shadow;
}

// Whether the light's shadow map decides the point at all: it has shadows and a cascade covers the point.
bool directionalShadowReaches(int slot, CascadeSelection s)
{
    return slot >= 0 && s.strength > 0.0;
}

// The realtime shadow with the distance and cascade fades, before the light's strength (1 = lit; 1 without a slot).
float directionalRealtimeShadow(int slot, CascadeSelection s, vec3 position, vec3 normal, vec3 towardsLight)
{
    if (!directionalShadowReaches(slot, s))
        return 1.0;
    return mix(1.0, directionalShadowVisibility(slot, s, position, normal, towardsLight), s.strength);
}

// 1 = fully lit. `slot` is the light's shadow slot, -1 for a light without shadows.
float directionalShadowAttenuation(int slot, CascadeSelection s, vec3 position, vec3 normal, vec3 towardsLight)
{
    if (!directionalShadowReaches(slot, s))
        return 1.0;
    const float strength = shadows.lights[slot].strength * s.strength;
    return mix(1.0, directionalShadowVisibility(slot, s, position, normal, towardsLight), strength);
}
