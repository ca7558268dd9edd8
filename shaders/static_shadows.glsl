// Static shadow maps (penumbra::shadows::StaticShadowUniforms): the static casters' depth of each light, kept
// between frames or baked, mixed with the realtime shadow as Unity's shadow masks are (Catlike Coding's "Shadow
// Masks" tutorial, MixBakedAndRealtimeShadows in its "Always" mode): the realtime shadow, faded out beyond the
// shadow distance, and the static one combine by taking the darker, then the light's strength applies; a light
// without realtime tiles keeps its static shadow. Needs directional_shadows.glsl and local_shadows.glsl first.

#include "static_shadows_block.glsl"

// Read with texelFetch (shadow_filter.glsl), as the realtime atlases.
layout(binding = PENUMBRA_BINDING_STATIC_DIRECTIONAL_ATLAS) uniform sampler2D staticDirectionalAtlas;
layout(binding = PENUMBRA_BINDING_STATIC_LOCAL_ATLAS) uniform sampler2D staticLocalAtlas;

// Directional light `light`'s static map at a receiver (1 = lit), its normal offset as the cascades' over the
// map's texel diagonal, filtered as the light's cascades are.
float staticDirectionalVisibility(StaticDirectionalLight light, vec3 position, vec3 normal, vec3 towardsLight)
{
    const int tile = light.tile;
    precise vec3 biased = position + receiverNormalOffset(normal, towardsLight, light.normalOffset);
    const TileTexelBounds bounds = staticShadows.directionalBounds[tile];
    const vec3 p = transformPoint(staticShadows.directionalWorldToMap[tile], biased).xyz;
    // The map covers the static casters' bounding sphere: a receiver beside it (a dynamic object moved away) has no
    // static caster between it and the light.
    const vec2 texel = p.xy * staticShadows.directionalAtlasSize;
    if (any(lessThan(texel, vec2(bounds.first))) || any(greaterThan(texel, vec2(bounds.last) + 1.0)))
        return 1.0;
    return filterDirectionalTile(staticDirectionalAtlas, p, staticShadows.directionalAtlasSize, bounds,
                                 light.shadowFilter, mat3(staticShadows.directionalWorldToMap[tile]),
                                 staticShadows.directionalSoft[tile], staticShadows.directionalSource[tile].tanHalfAngle,
                                 staticShadows.directionalSource[tile].texelWorldSize);
}

// A spot or point light's static map at a receiver (1 = lit), biased and filtered as its realtime tiles are.
float staticLocalVisibility(int firstTile, bool isPoint, vec3 lightPosition, vec3 axis, vec3 position, vec3 normal)
{
    const vec3 fromLight = position - lightPosition;
    const LocalTile local = localTile(firstTile, isPoint, axis, fromLight);
    const LocalShadowTile data = staticShadows.localTiles[local.tile];
    const mat4 m = staticShadows.localWorldToMap[local.tile];
    const vec4 p = localShadowPosition(m, data.normalBias, local.plane, fromLight, position, normal);
    return filterLocalTile(staticLocalAtlas, staticShadows.localAtlasSize, m, p, staticShadows.localBounds[local.tile],
                           data.shadowFilter, staticShadows.localSoft[local.tile]);
}

// Directional light `light` (the lit pass's index; `slot` its realtime shadow slot or -1) at a receiver, 1 = lit.
float directionalAttenuation(int light, int slot, bool receives, CascadeSelection s, vec3 position, vec3 normal,
                             vec3 towardsLight)
{
    const StaticDirectionalLight map = staticShadows.directionalLights[light];
    if (!receives)
        return 1.0;
    if (map.tile < 0)
        return directionalShadowAttenuation(slot, s, position, normal, towardsLight);
    const float realtime = directionalRealtimeShadow(slot, s, position, normal, towardsLight);
    return mix(1.0, min(realtime, staticDirectionalVisibility(map, position, normal, towardsLight)), map.strength);
}

// A spot or point light (`map` its static map, `tile` its first realtime tile or cube, or -1, `lightStrength` its
// shadow strength) at a receiver, 1 = lit. `strength` is the global one (distance fade).
float localAttenuation(StaticLocalLightMap map, int tile, float lightStrength, bool receives, bool isPoint,
                       vec3 lightPosition, vec3 axis, vec3 position, vec3 normal, float strength)
{
    if (!receives)
        return 1.0;
    if (map.tile < 0)
        return localShadowAttenuation(tile, lightStrength, isPoint, lightPosition, axis, position, normal, strength);
    const float realtime = localRealtimeShadow(tile, isPoint, lightPosition, axis, position, normal, strength);
    return mix(1.0, min(realtime, staticLocalVisibility(map.tile, isPoint, lightPosition, axis, position, normal)),
               map.strength);
}
