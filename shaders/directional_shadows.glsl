// Directional shadow attenuation: cascade selection, fades, normal bias and tent-filtered PCF over
// the atlas. The uniform block is penumbra::shadows::DirectionalShadowUniforms; the filter is the
// same math as penumbra::shadows::tentFilterTaps.

layout(std140, binding = 2) uniform DirectionalShadows {
    mat4 worldToAtlas[16];
    vec4 cullingSpheres[4];
    vec4 cascadeData[4];
    vec4 distanceFade;
    vec4 atlasSize;
    ivec4 config;
    vec4 lightShadowData[4];
} shadows;

// Read with texelFetch: the bilinear comparison is built from nearest comparisons on every backend
// (lavapipe cannot filter depth linearly, conventions note section 4).
layout(binding = 3) uniform sampler2D shadowAtlas;

const int PENUMBRA_BLEND_SOFT = 1;
const int PENUMBRA_BLEND_DITHER = 2;

struct CascadeSelection {
    int index;      // cascadeCount when the point is beyond every cascade
    float blend;    // weight of `index` against index + 1 (soft blend), 1 elsewhere
    float strength; // distance and last-cascade fade
};

// saturate((1 - distance * scale) * fade), the design document's FadedShadowStrength.
float fadedShadowStrength(float distance, float scale, float fade)
{
    return clamp((1.0 - distance * scale) * fade, 0.0, 1.0);
}

CascadeSelection selectCascade(vec3 position, float viewDepth, float dither)
{
    CascadeSelection s;
    s.blend = 1.0;
    s.strength = fadedShadowStrength(viewDepth, shadows.distanceFade.x, shadows.distanceFade.y);
    const int count = shadows.config.x;
    int i = 0;
    for (; i < count; ++i) {
        const vec4 sphere = shadows.cullingSpheres[i];
        const vec3 offset = position - sphere.xyz;
        const float distanceSquared = dot(offset, offset);
        if (distanceSquared < sphere.w) {
            const float fade = fadedShadowStrength(distanceSquared, shadows.cascadeData[i].x, shadows.distanceFade.z);
            if (i == count - 1)
                s.strength *= fade;
            else
                s.blend = fade;
            break;
        }
    }
    if (i == count)
        s.strength = 0.0;
    else if (shadows.config.z == PENUMBRA_BLEND_DITHER && s.blend < dither)
        i += 1;
    if (shadows.config.z != PENUMBRA_BLEND_SOFT)
        s.blend = 1.0;
    s.index = i;
    return s;
}

// 1 where the stored caster is not nearer to the light than the receiver (lit), else 0.
float compareTexel(ivec2 texel, float receiverDepth)
{
    return penumbraIsNearer(texelFetch(shadowAtlas, texel, 0).r, receiverDepth) ? 0.0 : 1.0;
}

// A bilinear comparison tap at texel-space position `position` (texel i spans [i, i + 1)), its four
// texels clamped to the tile so that no filter reads a neighbouring tile.
float bilinearCompare(vec2 position, float receiverDepth, ivec2 tileMin, ivec2 tileMax)
{
    const vec2 corner = position - 0.5;
    const vec2 base = floor(corner);
    const vec2 f = corner - base;
    const ivec2 t0 = clamp(ivec2(base), tileMin, tileMax);
    const ivec2 t1 = clamp(ivec2(base) + 1, tileMin, tileMax);
    const float top = mix(compareTexel(t0, receiverDepth), compareTexel(ivec2(t1.x, t0.y), receiverDepth), f.x);
    const float bottom = mix(compareTexel(ivec2(t0.x, t1.y), receiverDepth), compareTexel(t1, receiverDepth), f.x);
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

// PCF 2x2 (one bilinear tap) or the 3x3, 5x5, 7x7 tents (4, 9, 16 taps) at atlas position (u, v, depth).
float filterDirectionalShadow(vec3 atlasPosition, int tile)
{
    const int split = int(shadows.atlasSize.x * shadows.atlasSize.w + 0.5);
    const int tileSize = int(shadows.atlasSize.z);
    const ivec2 tileMin = ivec2(tile % split, tile / split) * tileSize;
    const ivec2 tileMax = tileMin + tileSize - 1;
    const vec2 texel = atlasPosition.xy * shadows.atlasSize.x;
    const int filterIndex = shadows.config.y;
    if (filterIndex == 0)
        return bilinearCompare(texel, atlasPosition.z, tileMin, tileMax);
    const int n = 2 * filterIndex + 1;
    const TentAxis u = tentTaps(n, texel.x);
    const TentAxis v = tentTaps(n, texel.y);
    const int pairs = (n + 1) / 2;
    float shadow = 0.0;
    for (int y = 0; y < pairs; ++y)
        for (int x = 0; x < pairs; ++x)
            shadow += u.weights[x] * v.weights[y] *
                      bilinearCompare(vec2(u.positions[x], v.positions[y]), atlasPosition.z, tileMin, tileMax);
    return shadow;
}

// The receiver moved along its normal by the cascade's filter-sized texel diagonal (normal bias), then filtered.
float sampleCascade(int tile, int cascade, vec3 position, vec3 normal, float normalBias)
{
    precise vec3 biased = fma(normal, vec3(normalBias * shadows.cascadeData[cascade].y), position);
    return filterDirectionalShadow(transformPoint(shadows.worldToAtlas[tile], biased).xyz, tile);
}

// 1 = fully lit. `slot` is the light's shadow slot, -1 for a light without shadows.
float directionalShadowAttenuation(int slot, CascadeSelection s, vec3 position, vec3 normal)
{
    if (slot < 0 || s.strength <= 0.0)
        return 1.0;
    const vec4 light = shadows.lightShadowData[slot];
    const int tile = int(light.z) + s.index;
    float shadow = sampleCascade(tile, s.index, position, normal, light.y);
    if (s.blend < 1.0)
        shadow = mix(sampleCascade(tile + 1, s.index + 1, position, normal, light.y), shadow, s.blend);
    return mix(1.0, shadow, light.x * s.strength);
}
