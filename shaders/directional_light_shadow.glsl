// A directional light's shadow at a receiver, 1 = lit, as the shader is built: mixed with its static map
// (static_shadows.glsl) where PENUMBRA_STATIC_SHADOWS compiles them in, the realtime cascades alone otherwise. The
// lit pass and the screen-space collection both call it, so the two paths evaluate one function. `light` is the lit
// pass's index, `slot` its realtime shadow slot or -1. Needs lit_constants.glsl (PENUMBRA_STATIC_SHADOWS),
// directional_shadows.glsl and, with static shadows, static_shadows.glsl first.

float directionalLightShadow(int light, int slot, bool receives, CascadeSelection s, vec3 position, vec3 normal,
                             vec3 towardsLight)
{
#if PENUMBRA_STATIC_SHADOWS
    return directionalAttenuation(light, slot, receives, s, position, normal, towardsLight);
#else
    return directionalShadowAttenuation(receives ? slot : -1, s, position, normal, towardsLight);
#endif
}
