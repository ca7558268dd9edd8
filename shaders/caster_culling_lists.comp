#version 450
// Second dispatch of the GPU caster culling (penumbra::shadows::GpuCasterCulling): one workgroup per tile walks the
// tile's bits from caster_culling.comp in the batches' order, 64 places a step, and gives each marked caster the
// slot its rank says (a stream compaction by prefix counts, Blelloch, "Prefix Sums and Their Applications", 1990).
// So each tile's list holds its casters in caster order within each batch, the same every run, where atomics gave
// them in whatever order the lanes came (and a random order costs llvmpipe's atlas pass some 13 %).

layout(local_size_x = 64) in;

#include "culling_blocks.glsl"

void main()
{
    const uint tile = gl_WorkGroupID.x;
    const uint lane = gl_LocalInvocationID.x;
    const uint words = (tiles.tileSlots + 31u) / 32u;
    const uint bitsBase = (tiles.firstTile + tile) * words;
    const uint commandBase = (tiles.firstTile + tile) * tiles.batchCount;
    const uint slotBase = (tiles.firstTile + tile) * tiles.tileSlots;
    // The tile's casters placed before this step: the same in every lane.
    uint placed = 0u;
    for (uint step = 0u; step < tiles.casterCount; step += 64u) {
        const uint low = marks.bits[bitsBase + step / 32u];
        const uint high = step / 32u + 1u < words ? marks.bits[bitsBase + step / 32u + 1u] : 0u;
        const uint word = lane < 32u ? low : high;
        const uint bit = lane % 32u;
        const uint rank = placed + (lane < 32u ? 0u : bitCount(low)) + bitCount(word & ((1u << bit) - 1u));
        const uint place = step + lane;
        if (place < tiles.casterCount) {
            const uint caster = casterOrder.order[place];
            const CullingCaster c = casterList.casters[caster];
            // Batches take consecutive places, so a batch's instances start at its first place's rank.
            if (place == c.first)
                draws.commands[commandBase + c.batch].firstInstance = slotBase + rank;
            if ((word & (1u << bit)) != 0u) {
                // The dispatch binds its own tiles' ranges of the instance lists.
                culled.instances[tile * tiles.tileSlots + rank] = source.transforms[caster];
                culledIndices.indices[tile * tiles.tileSlots + rank] = caster;
            }
        }
        placed += bitCount(low) + bitCount(high);
    }
    memoryBarrierBuffer();
    barrier();
    // A batch's count: up to the next batch's first instance, the last's up to the tile's end.
    for (uint b = lane; b < tiles.batchCount; b += 64u) {
        const uint first = draws.commands[commandBase + b].firstInstance;
        const uint end = b + 1u < tiles.batchCount ? draws.commands[commandBase + b + 1u].firstInstance : slotBase + placed;
        draws.commands[commandBase + b].instanceCount = end - first;
        drawCounts.counts[commandBase + b] = end > first ? 1u : 0u;
    }
}
