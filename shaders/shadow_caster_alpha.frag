#version 450
// Clip casters drop texels below the alpha cutoff; dither casters keep a texel where alpha
// reaches the interleaved-gradient dither (alpha as coverage), taken in world-anchored texels so that
// the stable cascades' whole-texel moves do not make dithered shadows tremble.

#include "material.glsl"
#include "shadow_caster.glsl"

layout(location = 0) in vec2 vUv;

void main()
{
    const int mode = int(draw.material.z);
    const float alpha = materialAlpha(draw.material.x, mode, vUv);
    const float threshold = mode == PENUMBRA_CASTER_DITHER ? interleavedGradientNoise(gl_FragCoord.xy + draw.ditherOrigin.xy) : draw.material.y;
    if (alpha < threshold)
        discard;
}
