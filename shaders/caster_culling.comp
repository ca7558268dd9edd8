#version 450
// Shadow casters culled per tile on the GPU (penumbra::shadows::GpuCasterCulling), first of two dispatches: each
// invocation tests one caster's world box against every tile's volume and marks it in the tile's bits;
// caster_culling_lists.comp then lays each tile's marked casters out in order. The tests mirror
// shadows/src/CasterVolume.cpp (casterInVolume, the planner's rules) operation for operation, so the lists are the
// CPU's; the box's light-space bounds are Arvo's ("Transforming Axis-Aligned Bounding Boxes", Graphics Gems, 1990).

layout(local_size_x = 64) in;

#include "constants.glsl"
#include "culling_blocks.glsl"

vec3 boxCorner(vec3 lo, vec3 hi, int i)
{
    return vec3((i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y, (i & 4) != 0 ? hi.z : lo.z);
}

// meetsFrustum: culled where all 8 corners lie outside one of the six planes (view space, looking down -z).
bool meetsFrustum(vec3 lo, vec3 hi, CasterVolume v)
{
    const float tx = v.frustum.x, ty = v.frustum.w;
    int outside[6] = int[6](0, 0, 0, 0, 0, 0);
    for (int i = 0; i < 8; ++i) {
        const vec3 p = (v.view * vec4(boxCorner(lo, hi, i), 1.0)).xyz;
        const float depth = -p.z;
        outside[0] += depth < v.frustum.y ? 1 : 0;
        outside[1] += depth > v.frustum.z ? 1 : 0;
        outside[2] += p.x > depth * tx ? 1 : 0;
        outside[3] += -p.x > depth * tx ? 1 : 0;
        outside[4] += p.y > depth * ty ? 1 : 0;
        outside[5] += -p.y > depth * ty ? 1 : 0;
    }
    for (int k = 0; k < 6; ++k)
        if (outside[k] == 8)
            return false;
    return true;
}

// overlapsCascade over lightSpaceBounds: the light box meets the tile's square and begins before its far plane.
bool overlapsCascade(vec3 lo, vec3 hi, CasterVolume v)
{
    const vec3 mid = 0.5 * (lo + hi);
    const vec3 centre = vec3(dot(mid, v.right.xyz), dot(mid, v.up.xyz), dot(mid, v.direction.xyz));
    const vec3 halfSize = 0.5 * (hi - lo);
    const vec3 reach =
        vec3(dot(abs(v.right.xyz), halfSize), dot(abs(v.up.xyz), halfSize), dot(abs(v.direction.xyz), halfSize));
    const vec3 lightMin = centre - reach;
    const vec3 lightMax = centre + reach;
    const float h = v.square.z;
    return lightMax.x >= v.square.x - h && lightMin.x <= v.square.x + h && lightMax.y >= v.square.y - h &&
           lightMin.y <= v.square.y + h && lightMin.z <= v.square.w;
}

// heldByPrevious, the culling bias: the world box lies wholly inside the previous cascade's scaled sphere or slice.
bool heldByPrevious(vec3 lo, vec3 hi, CasterVolume v)
{
    if (v.kind == PENUMBRA_VOLUME_BEYOND_SPHERE) {
        const vec3 farthest = max(abs(lo - v.sphere.xyz), abs(hi - v.sphere.xyz));
        return dot(farthest, farthest) <= v.sphere.w * v.sphere.w;
    }
#if PENUMBRA_CULL_SLICES
    if (v.kind != PENUMBRA_VOLUME_BEYOND_SLICE)
        return false;
    for (int i = 0; i < 8; ++i) {
        const vec3 offset = boxCorner(lo, hi, i) - v.slicePosition.xyz;
        const float depth = dot(offset, v.sliceForward.xyz);
        if (depth < v.slicePosition.w || depth > v.sliceForward.w ||
            abs(dot(offset, v.sliceRight.xyz)) > depth * v.sliceRight.w ||
            abs(dot(offset, v.sliceUp.xyz)) > depth * v.sliceUp.w)
            return false;
    }
    return true;
#else
    return false;
#endif
}

// The kinds the dispatch's tiles hold (PENUMBRA_CULL_*, GpuCasterCulling::testPipeline) are tested; the code of the
// others is left out, since llvmpipe runs every branch for every lane.
bool casterInVolume(vec3 lo, vec3 hi, CasterVolume v)
{
#if PENUMBRA_CULL_FRUSTUMS
    if (v.kind == PENUMBRA_VOLUME_FRUSTUM)
        return meetsFrustum(lo, hi, v);
#endif
#if PENUMBRA_CULL_CASCADES
    return overlapsCascade(lo, hi, v) && !heldByPrevious(lo, hi, v);
#else
    return false;
#endif
}

// Each workgroup's 64 places' bits of every tile, gathered here so that each word is stored once, whole: llvmpipe
// runs a storage atomic lane by lane, and a host clear of every tile's bits each frame is not needed.
shared uint tileBits[2 * PENUMBRA_CULLING_TILES];

// Invocation i tests the caster at place i of the batches' order and sets bit i of each tile that holds it.
void main()
{
    const uint lane = gl_LocalInvocationID.x;
    for (uint w = lane; w < 2u * tiles.tileCount; w += 64u)
        tileBits[w] = 0u;
    memoryBarrierShared();
    barrier();
    const uint place = gl_GlobalInvocationID.x;
    if (place < tiles.casterCount) {
        const CullingCaster c = casterList.casters[casterOrder.order[place]];
        for (uint tile = 0u; tile < tiles.tileCount; ++tile)
            if (casterInVolume(c.boundsMin.xyz, c.boundsMax.xyz, tiles.volumes[tile]))
                atomicOr(tileBits[tile * 2u + lane / 32u], 1u << (lane % 32u));
    }
    memoryBarrierShared();
    barrier();
    for (uint w = lane; w < 2u * tiles.tileCount; w += 64u)
        marks.bits[(tiles.firstTile + w / 2u) * tiles.markWords + gl_WorkGroupID.x * 2u + w % 2u] = tileBits[w];
}
