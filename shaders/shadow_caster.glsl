// Per-draw uniforms of the shadow caster pass (penumbra::shadows::ShadowCasterUniforms).
layout(std140, binding = PENUMBRA_BINDING_CASTER_DRAW) uniform ShadowCasterDraw {
    mat4 viewProjection; // the view's light view-projection
    vec4 material;     // alpha, alpha cutoff, caster mode (material.glsl), 1 to pancake in the shader
    vec4 sampling;     // xy: added to gl_FragCoord, so the dither follows the world-fixed texel grid;
                       // z: 1 when the caster's alpha comes from its base colour texture
    vec4 baseColorUv[2]; // the base colour texture's uv transform and set (material.glsl, transformedUv)
    // The caster-side normal offset (penumbra::shadows::CasterNormalOffset), only read where reach.x > 0:
    vec4 light;          // xyz: direction into the scene (w = 0) or the light's position (w = 1)
    vec4 reach;          // x: the lookup reach in world units, per unit of distance from the light where light.w = 1
} draw;
