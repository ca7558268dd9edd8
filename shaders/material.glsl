// Material facts shared by the caster and lit passes; the same math as penumbra::scene::materialAlpha.

#include "caster_constants.glsl"

// Clip materials without a texture get a checker of holes, 5 cells per uv unit (scene::kClipCheckerCells);
// textured ones take the texture's alpha (`textureAlpha`, 1 without a texture).
// Chosen with mix(a, b, bool), not branches on the material's uniforms (shadow_caster.vert says why).
float materialAlpha(float baseAlpha, int casterMode, vec2 uv, bool textured, float textureAlpha)
{
    const ivec2 cell = ivec2(floor(uv * 5.0));
    const float checker = mix(0.0, baseAlpha, ((cell.x + cell.y) & 1) == 0);
    const float untextured = mix(baseAlpha, checker, casterMode == PENUMBRA_CASTER_CLIP);
    return mix(untextured, baseAlpha * textureAlpha, textured);
}

// A texture's uv (KHR_texture_transform): rows[0].w picks TEXCOORD_0 or TEXCOORD_1 (textureInfo.texCoord), rows 0
// and 1 of the transform's 3 x 3 matrix map it (penumbra::shadows::uvTransformRows packs them).
vec2 transformedUv(vec4 rows[2], vec2 uv0, vec2 uv1)
{
    const vec3 uv = vec3(mix(uv0, uv1, bvec2(rows[0].w > 0.5)), 1.0);
    return vec2(dot(rows[0].xyz, uv), dot(rows[1].xyz, uv));
}

// Jimenez 2014, "Next Generation Post Processing in Call of Duty: Advanced Warfare": a dither in
// [0, 1) per pixel that looks like blue noise. gl_FragCoord counts rows from the top on every backend.
float interleavedGradientNoise(vec2 pixel)
{
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}
