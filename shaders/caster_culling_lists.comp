#version 450
// Second dispatch of the GPU caster culling (penumbra::shadows::GpuCasterCulling): one workgroup per tile walks the
// tile's bits from caster_culling.comp in the batches' order and gives each marked caster the slot its rank says (a
// stream compaction by prefix counts, Blelloch, "Prefix Sums and Their Applications", 1990). So each tile's list
// holds its casters in caster order within each batch, the same every run, where atomics gave them in whatever order
// the lanes came (and a random order costs llvmpipe's atlas pass some 13 %).
//
// A lane takes a word of 32 places, and a run of 64 words is ranked first, its casters copied after, one a lane:
// llvmpipe (Mesa 22.3) loads and stores storage and shared memory one lane and one word at a time for every lane of
// a vector, active or not, so the work goes by words and by marked casters rather than by places.

layout(local_size_x = 64) in;

#include "culling_blocks.glsl"

const uint kRunPlaces = 64u * 32u;
// The run's words, their marked places' count, its prefix sums (two buffers: Hillis and Steele, "Data Parallel
// Algorithms", 1986) and the marked places by rank within the run.
shared uint runBits[64];
shared uint runSums[2][64];
shared uint runPlaces[kRunPlaces];

void main()
{
    const uint tile = gl_WorkGroupID.x;
    const uint lane = gl_LocalInvocationID.x;
    const uint bitsBase = (tiles.firstTile + tile) * tiles.markWords;
    const uint commandBase = (tiles.firstTile + tile) * tiles.batchCount;
    const uint slotBase = (tiles.firstTile + tile) * tiles.tileSlots;
    // The dispatch binds its own tiles' ranges of the instance lists.
    const uint listBase = tile * tiles.tileSlots;
    // The tile's casters placed before this run: the same in every lane.
    uint placed = 0u;
    // Lane 0 sets the draws: the next batch, and the rank its predecessor began at.
    uint batch = 0u;
    uint batchStart = 0u;
    for (uint run = 0u; run < tiles.casterCount; run += kRunPlaces) {
        const uint first = run + lane * 32u;
        const uint bits = first < tiles.casterCount ? marks.bits[bitsBase + first / 32u] : 0u;
        runBits[lane] = bits;
        runSums[0][lane] = bitCount(bits);
        memoryBarrierShared();
        barrier();
        uint from = 0u;
        for (uint reach = 1u; reach < 64u; reach *= 2u) {
            const uint sum = runSums[from][lane] + (lane >= reach ? runSums[from][lane - reach] : 0u);
            runSums[1u - from][lane] = sum;
            from = 1u - from;
            memoryBarrierShared();
            barrier();
        }
        // The marked places before this lane's word, in the run.
        const uint before = runSums[from][lane] - bitCount(bits);
        for (uint rest = bits, rank = before; rest != 0u; rest &= rest - 1u, ++rank)
            runPlaces[rank] = first + uint(findLSB(rest));
        // Each batch's instances begin at the rank of its first place (the host's firstInstance: the tile range's
        // start plus that place, read before it is written).
        if (lane == 0u)
            while (batch < tiles.batchCount) {
                const uint batchFirst = draws.commands[commandBase + batch].firstInstance - slotBase;
                if (batchFirst >= run + kRunPlaces)
                    break;
                const uint word = (batchFirst - run) / 32u;
                const uint wordBits = runBits[word];
                const uint rank = placed + runSums[from][word] - bitCount(wordBits) +
                                  bitCount(wordBits & ((1u << (batchFirst % 32u)) - 1u));
                if (batch > 0u) {
                    draws.commands[commandBase + batch - 1u].instanceCount = rank - batchStart;
                    drawCounts.counts[commandBase + batch - 1u] = rank > batchStart ? 1u : 0u;
                }
                draws.commands[commandBase + batch].firstInstance = slotBase + rank;
                batchStart = rank;
                ++batch;
            }
        const uint runCount = runSums[from][63];
        memoryBarrierShared();
        barrier();
        for (uint rank = lane; rank < runCount; rank += 64u) {
            const uint caster = casterOrder.order[runPlaces[rank]];
            culled.instances[listBase + placed + rank] = source.transforms[caster];
            culledIndices.indices[listBase + placed + rank] = caster;
        }
        placed += runCount;
        barrier();
    }
    if (lane == 0u) {
        draws.commands[commandBase + batch - 1u].instanceCount = placed - batchStart;
        drawCounts.counts[commandBase + batch - 1u] = placed > batchStart ? 1u : 0u;
    }
}
