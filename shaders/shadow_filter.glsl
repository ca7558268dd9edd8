// Tent-filtered percentage-closer filtering over one tile of a depth atlas, shared by directional,
// spot and point shadows. The same math as penumbra::shadows::tentFilterTaps. Atlases are read raw (texelFetch,
// textureGather): the bilinear comparison is built from nearest comparisons on every backend (lavapipe
// cannot filter depth linearly, conventions note section 4).

#include "normal_offset.glsl"
#include "shadow_constants.glsl"

// 1 where the stored caster is not nearer to the light than the receiver (lit), else 0.
float compareTexel(sampler2D atlas, ivec2 texel, float receiverDepth)
{
    return penumbraIsNearer(texelFetch(atlas, texel, 0).r, receiverDepth) ? 0.0 : 1.0;
}

// A bilinear comparison tap at texel-space position `position` (texel i spans [i, i + 1)) over texels tileMin..tileMax
// only, so that no filter reads a neighbouring tile: a position beyond the tile's outer texel centres takes the
// outer texels, as clamping each texel to the tile would. The four texels come from one textureGather at their
// shared corner (GLSL 4.50 specification, "Texture Gather Functions": x = (i0, j1), y = (i1, j1), z = (i1, j0),
// w = (i0, j0)); at the tile's far edge the texel past it gets the weight 0.
float bilinearCompare(sampler2D atlas, vec2 position, float receiverDepth, ivec2 tileMin, ivec2 tileMax)
{
    const vec2 corner = clamp(position, vec2(tileMin) + 0.5, vec2(tileMax) + 0.5) - 0.5;
    const vec2 base = floor(corner);
    const vec2 f = corner - base;
    const vec4 depths = textureGather(atlas, (base + 1.0) / vec2(textureSize(atlas, 0)), 0);
    const vec4 lit = vec4(penumbraIsNearer(depths.x, receiverDepth) ? 0.0 : 1.0,
                          penumbraIsNearer(depths.y, receiverDepth) ? 0.0 : 1.0,
                          penumbraIsNearer(depths.z, receiverDepth) ? 0.0 : 1.0,
                          penumbraIsNearer(depths.w, receiverDepth) ? 0.0 : 1.0);
    const float top = mix(lit.w, lit.z, f.x);
    const float bottom = mix(lit.x, lit.y, f.x);
    return mix(top, bottom, f.y);
}

// Cumulative integral of the unit-area tent of half width h from -h to x.
float tentCdf(float x, float h)
{
    const float u = clamp(x / h, -1.0, 1.0);
    return u < 0.0 ? 0.5 * (1.0 + u) * (1.0 + u) : 1.0 - 0.5 * (1.0 - u) * (1.0 - u);
}

// One axis of an n-texel tent at texel-space `centre`: n + 1 texel weights merged pairwise into
// (n + 1) / 2 bilinear taps, each placed b / (a + b) past its first texel's centre.
struct TentAxis {
    vec4 positions; // texel space
    vec4 weights;
};

TentAxis tentTaps(int n, float centre)
{
    const float h = 0.5 * float(n);
    const int first = int(floor(centre + 0.5)) - (n + 1) / 2;
    TentAxis axis;
    for (int p = 0; p < 4; ++p) {
        const float left = float(first + 2 * p) - centre;
        const float a = tentCdf(left + 1.0, h) - tentCdf(left, h);
        const float b = tentCdf(left + 2.0, h) - tentCdf(left + 1.0, h);
        const float sum = a + b;
        axis.positions[p] = float(first + 2 * p) + 0.5 + (sum > 0.0 ? b / sum : 0.5);
        axis.weights[p] = sum;
    }
    return axis;
}

// The 3x3, 5x5, 7x7 tents (4, 9, 16 taps, filterIndex 1 to 3) at texel-space position `texel`.
float tentFilter(sampler2D atlas, vec2 texel, float receiverDepth, int filterIndex, ivec2 tileMin, ivec2 tileMax)
{
    const int n = 2 * filterIndex + 1;
    const TentAxis u = tentTaps(n, texel.x);
    const TentAxis v = tentTaps(n, texel.y);
    const int pairs = (n + 1) / 2;
    float shadow = 0.0;
    for (int y = 0; y < pairs; ++y)
        for (int x = 0; x < pairs; ++x)
            shadow += u.weights[x] * v.weights[y] *
                      bilinearCompare(atlas, vec2(u.positions[x], v.positions[y]), receiverDepth, tileMin, tileMax);
    return shadow;
}

// PCF 2x2 (one bilinear tap) or the tents at atlas position (u, v, depth); the tents only where the shader is built
// with them (PENUMBRA_TENT_FILTERS).
// Taps read only texels tileMin..tileMax: clamping texels is clamping tap positions to the tile shrunk by
// half a texel, so no filter or normal bias reads a neighbouring tile.
float filterShadowTile(sampler2D atlas, vec3 atlasPosition, float atlasSize, int filterIndex, ivec2 tileMin,
                       ivec2 tileMax)
{
    const vec2 texel = atlasPosition.xy * atlasSize;
#if PENUMBRA_TENT_FILTERS
    if (filterIndex > 0)
        return tentFilter(atlas, texel, atlasPosition.z, filterIndex, tileMin, tileMax);
#endif
    return bilinearCompare(atlas, texel, atlasPosition.z, tileMin, tileMax);
}
