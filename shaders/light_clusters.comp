#version 450
// The clustered light lists built on the GPU (penumbra::shadows::GpuLightClusters) in three stages: PENUMBRA_STAGE 0
// counts each cluster's lights, 1 sums the counts in cluster order into each cluster's first entry and writes its
// range, 2 writes each cluster's lights from there, ascending. The tests mirror shadows/src/local/LightClusters.cpp
// (clusterBoxes, lightMeetsBox) operation for operation, in the same order, from the same per-light bounds and edges
// (LightClusterInputs), with `precise` so that no compiler fuses a multiply and an add the CPU rounds apart: the lists
// are the CPU's (Olsson, Billeter and Assarsson, "Clustered Deferred and Forward Shading", HPG 2012).
#include "constants.glsl"
#include "light_cluster_blocks.glsl"

#if PENUMBRA_STAGE == 1
const uint kSumInvocations = 128; // the least maxComputeWorkGroupInvocations Vulkan allows
layout(local_size_x = kSumInvocations) in;
shared uint partialSums[kSumInvocations];
#else
layout(local_size_x = 64) in;
#endif

int clusterTotal() { return grid.gridSize.x * grid.gridSize.y * grid.gridSize.z; }

ivec2 dataTexel(int t) { return ivec2(t & ((1 << grid.dataLayout.x) - 1), t >> grid.dataLayout.x); }

#if PENUMBRA_STAGE != 1
struct ClusterBox {
    vec3 lo;
    vec3 hi;
};

// clusterBoxes: the view-space box around the cluster's eight corners, widened by the margin times its far depth.
// Returned, not written to out parameters, which SPIRV-Cross turns into temporaries Mesa warns are uninitialized.
ClusterBox clusterBox(ivec3 cell)
{
    const int firstY = grid.gridSize.x + 1;
    const int firstDepth = firstY + grid.gridSize.y + 1;
    const float depths[2] = float[2](grid.edges[firstDepth + cell.z], grid.edges[firstDepth + cell.z + 1]);
    vec3 lo = vec3(uintBitsToFloat(0x7f800000u));
    vec3 hi = -lo;
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                const vec2 ndc = vec2(grid.edges[cell.x + i], grid.edges[firstY + cell.y + j]);
                precise vec3 p = vec3(ndc * grid.view.xy * depths[k], depths[k]);
                lo = min(lo, p);
                hi = max(hi, p);
            }
    precise vec3 margin = vec3(grid.view.z * depths[1]);
    return ClusterBox(lo - margin, hi + margin);
}

bool sphereMeetsBox(vec4 s, vec3 lo, vec3 hi)
{
    precise vec3 d = clamp(s.xyz, lo, hi) - s.xyz;
    precise float distance2 = d.x * d.x + d.y * d.y + d.z * d.z;
    precise float radius2 = s.w * s.w;
    return distance2 <= radius2;
}

// lightMeetsBox: inside the bounding sphere, the range sphere and (a spot light) the cone, whose test takes the
// sphere around the box (sphereMeetsCone).
bool lightMeetsBox(ClusterLightBound l, vec3 lo, vec3 hi)
{
    if (l.axis.w == 0.0)
        return sphereMeetsBox(l.bound, lo, hi);
    if (!sphereMeetsBox(l.bound, lo, hi) || !sphereMeetsBox(l.reach, lo, hi))
        return false;
    precise vec3 centre = 0.5 * (lo + hi);
    precise vec3 extent = hi - lo;
    precise float radius = 0.5 * sqrt(extent.x * extent.x + extent.y * extent.y + extent.z * extent.z);
    precise vec3 v = centre - l.reach.xyz;
    precise float along = v.x * l.axis.x + v.y * l.axis.y + v.z * l.axis.z;
    precise float length2 = v.x * v.x + v.y * v.y + v.z * v.z;
    precise float across = sqrt(max(length2 - along * along, 0.0));
    precise float toSide = l.cone.x * across - l.cone.y * along;
    precise float beyond = radius + l.reach.w;
    return !(toSide > radius || along > beyond || along < -radius);
}

bool lightInCell(ClusterLightBound l, ivec3 cell)
{
    return cell.x >= l.tiles.x && cell.x <= l.tiles.z && cell.y >= l.tiles.y && cell.y <= l.tiles.w &&
           cell.z >= l.slices.x && cell.z <= l.slices.y;
}

void main()
{
    const int cluster = int(gl_GlobalInvocationID.x);
    const int total = clusterTotal();
    if (cluster >= total)
        return;
    const int tiles = grid.gridSize.x * grid.gridSize.y;
    const ivec3 cell = ivec3(cluster % grid.gridSize.x, (cluster % tiles) / grid.gridSize.x, cluster / tiles);
    const ClusterBox box = clusterBox(cell);
#if PENUMBRA_STAGE == 2
    const int first = int(counts.clusterCounts[total + cluster]);
#endif
    uint found = 0u;
    for (int i = 0; i < grid.gridSize.w; ++i) {
        const ClusterLightBound l = lightBounds.lights[i];
        if (!lightInCell(l, cell) || !lightMeetsBox(l, box.lo, box.hi))
            continue;
#if PENUMBRA_STAGE == 2
        imageStore(lightIndices, dataTexel(first + int(found)), vec4(float(i)));
#endif
        ++found;
    }
#if PENUMBRA_STAGE == 0
    counts.clusterCounts[cluster] = found;
#endif
}
#else
// One workgroup: each invocation sums a run of consecutive clusters, the first turns the runs' sums into their first
// entries, and each writes its clusters' ranges.
void main()
{
    const int total = clusterTotal();
    const int run = (total + int(kSumInvocations) - 1) / int(kSumInvocations);
    const uint self = gl_LocalInvocationID.x;
    const int begin = min(int(self) * run, total);
    const int end = min(begin + run, total);
    uint sum = 0u;
    for (int c = begin; c < end; ++c)
        sum += counts.clusterCounts[c];
    partialSums[self] = sum;
    memoryBarrierShared();
    barrier();
    if (self == 0u) {
        uint first = 0u;
        for (uint k = 0u; k < kSumInvocations; ++k) {
            const uint s = partialSums[k];
            partialSums[k] = first;
            first += s;
        }
    }
    memoryBarrierShared();
    barrier();
    uint first = partialSums[self];
    for (int c = begin; c < end; ++c) {
        const uint count = counts.clusterCounts[c];
        counts.clusterCounts[total + c] = first;
        imageStore(clusterRanges, dataTexel(c), vec4(float(first), float(count), 0.0, 0.0));
        first += count;
    }
}
#endif
