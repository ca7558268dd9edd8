// Per-draw uniforms of the shadow caster pass (penumbra::shadows::ShadowCasterUniforms).
layout(std140, binding = 0) uniform ShadowCasterDraw {
    mat4 worldToClip;  // the cascade's light view-projection times the caster's model matrix
    vec4 material;     // alpha, alpha cutoff, caster mode (material.glsl), 1 to pancake in the shader
    vec4 sampling;     // xy: added to gl_FragCoord, so the dither follows the world-fixed texel grid;
                       // z: 1 when the caster's alpha comes from its base colour texture
    vec4 baseColorUv[2]; // the base colour texture's uv transform and set (material.glsl, transformedUv)
} draw;
