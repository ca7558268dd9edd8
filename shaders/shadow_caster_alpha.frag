#version 450
// Clip casters drop texels below the alpha cutoff; dither casters keep a texel where alpha
// reaches the interleaved-gradient dither (alpha as coverage), taken in world-anchored texels so that
// the stable cascades' whole-texel moves do not make dithered shadows tremble.

#include "material.glsl"
#include "caster_block.glsl"

layout(binding = PENUMBRA_BINDING_CASTER_BASE_COLOR) uniform sampler2D baseColorMap; // a white texel for untextured casters

layout(location = 0) in vec2 vUv;

void main()
{
    const int mode = draw.casterMode;
    const bool textured = draw.textured != 0;
    // Level 0: a texel's depth is the caster's at the texel's centre, so its coverage is too. A mip level averages
    // alpha over the texel's footprint and moves the cut-out edge by up to a texel (leaf cards grew and shrank
    // against the ray cast by a texel); the shadow map is point-sampled either way.
    const float alpha =
        materialAlpha(draw.alpha, mode, vUv, textured, textureLod(baseColorMap, vUv, 0.0).a);
    const float threshold = mix(draw.alphaCutoff, interleavedGradientNoise(gl_FragCoord.xy + draw.ditherOrigin),
                                mode == PENUMBRA_CASTER_DITHER);
    if (alpha < threshold)
        discard;
}
