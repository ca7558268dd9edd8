#version 450
// Second dispatch of the GPU caster culling (penumbra::shadows::GpuCasterCulling): workgroup (t, c) walks tile t's
// bits from caster_culling.comp over chunk c of the places (the batches' order) and gives each marked caster the
// slot its rank says (a stream compaction by prefix counts, Blelloch, "Prefix Sums and Their Applications", 1990),
// its chunk's first rank counted from the bits before it. So each tile's list holds its casters in caster order
// within each batch, the same every run, where atomics gave them in whatever order the lanes came (and a random order
// costs llvmpipe's atlas pass some 13 %), and the chunks of a long list are laid out at once.
//
// A lane takes a word of 32 places, and a run of 64 words is ranked first, its casters copied after, one a lane:
// llvmpipe (Mesa 22.3) loads and stores storage and shared memory one lane and one word at a time for every lane of
// a vector, active or not, so the work goes by words and by marked casters rather than by places.

#include "culling_blocks.glsl"

layout(local_size_x = 64) in;

const uint kRunPlaces = uint(PENUMBRA_CULLING_RUN_PLACES);
// The run's words, their marked places' count, its prefix sums (two buffers: Hillis and Steele, "Data Parallel
// Algorithms", 1986) and the marked places by rank within the run; the ranks of the chunk's runs' first places.
shared uint runBits[64];
shared uint runSums[2][64];
shared uint runPlaces[kRunPlaces];
shared uint runStarts[PENUMBRA_CULLING_CHUNK_RUNS];

// The first place of batch b; of batch batchCount, the caster count (GpuCasterCulling writes them after the order).
uint batchFirst(uint b) { return casterOrder.order[tiles.casterCount + b]; }

// The marked places before `place`, a place of the chunk beginning at `chunkStart`, in the tile whose bits begin at
// `bitsBase`: its run's first rank, then the run's words before it.
uint rankInChunk(uint bitsBase, uint chunkStart, uint place)
{
    const uint run = (place - chunkStart) / kRunPlaces;
    uint rank = runStarts[run];
    for (uint w = (chunkStart + run * kRunPlaces) / 32u; w < place / 32u; ++w)
        rank += bitCount(marks.bits[bitsBase + w]);
    return rank + bitCount(marks.bits[bitsBase + place / 32u] & ((1u << (place % 32u)) - 1u));
}

void main()
{
    const uint tile = gl_WorkGroupID.x;
    const uint lane = gl_LocalInvocationID.x;
    const uint bitsBase = (tiles.firstTile + tile) * tiles.markWords;
    const uint commandBase = (tiles.firstTile + tile) * tiles.batchCount;
    const uint slotBase = (tiles.firstTile + tile) * tiles.tileSlots;
    // The dispatch binds its own tiles' ranges of the instance lists.
    const uint listBase = tile * tiles.tileSlots;
    const uint chunkStart = gl_WorkGroupID.y * tiles.chunkRuns * kRunPlaces;
    const uint chunkEnd = min(chunkStart + tiles.chunkRuns * kRunPlaces, tiles.casterCount);
    // The batch that holds the chunk's first place: the last to begin at or before it.
    uint open = 0u;
    for (uint count = tiles.batchCount; count > 1u;) {
        const uint step = count / 2u;
        if (batchFirst(open + step) <= chunkStart)
            open += step;
        count -= step;
    }
    const uint openFirst = batchFirst(open);
    // The marked places before the chunk, and before the open batch's first place, a word a lane, then summed.
    uint before = 0u, beforeOpen = 0u;
    for (uint w = lane; w < chunkStart / 32u; w += 64u) {
        const uint bits = marks.bits[bitsBase + w];
        before += bitCount(bits);
        if (w < openFirst / 32u)
            beforeOpen += bitCount(bits);
        else if (w == openFirst / 32u)
            beforeOpen += bitCount(bits & ((1u << (openFirst % 32u)) - 1u));
    }
    runSums[0][lane] = before;
    runSums[1][lane] = beforeOpen;
    memoryBarrierShared();
    barrier();
    for (uint reach = 32u; reach > 0u; reach /= 2u) {
        if (lane < reach) {
            runSums[0][lane] += runSums[0][lane + reach];
            runSums[1][lane] += runSums[1][lane + reach];
        }
        memoryBarrierShared();
        barrier();
    }
    // The tile's casters placed before this run: the same in every lane.
    uint placed = runSums[0][0];
    const uint openRank = runSums[1][0];
    barrier();
    for (uint run = chunkStart; run < chunkEnd; run += kRunPlaces) {
        if (lane == 0u)
            runStarts[(run - chunkStart) / kRunPlaces] = placed;
        const uint first = run + lane * 32u;
        const uint bits = first < chunkEnd ? marks.bits[bitsBase + first / 32u] : 0u;
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
        const uint beforeWord = runSums[from][lane] - bitCount(bits);
        for (uint rest = bits, rank = beforeWord; rest != 0u; rest &= rest - 1u, ++rank)
            runPlaces[rank] = first + uint(findLSB(rest));
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
    memoryBarrierShared();
    barrier();
    // The draws, a batch a lane: a batch's first instance is set by the chunk of its first place, its count by the
    // chunk of its last (the batch that ends at a chunk's end ends with the chunk's last rank).
    for (uint b = open + lane; b < tiles.batchCount && batchFirst(b) < chunkEnd; b += 64u) {
        const uint begin = batchFirst(b), end = batchFirst(b + 1u);
        const uint beginRank = begin < chunkStart ? openRank : rankInChunk(bitsBase, chunkStart, begin);
        if (begin >= chunkStart)
            draws.commands[commandBase + b].firstInstance = slotBase + beginRank;
        if (end <= chunkEnd) {
            const uint endRank = end == chunkEnd ? placed : rankInChunk(bitsBase, chunkStart, end);
            draws.commands[commandBase + b].instanceCount = endRank - beginRank;
            drawCounts.counts[commandBase + b] = endRank > beginRank ? 1u : 0u;
        }
    }
}
