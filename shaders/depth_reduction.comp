#version 450
// The depth fit's histogram of the visible view depths (render/src/passes/DepthReduction.hpp,
// penumbra::shadows::DepthHistogram): each pixel the depth prepass drew is turned back into its world position, counted
// in the bin of its view depth (8 per power of two, shadows::depthHistogramBin) and, per shadowed directional light,
// widens that bin's light-space footprint. A workgroup gathers its 16 x 16 pixels in shared memory, then merges the
// bins it touched into the buffer with atomics (Lauritzen, Salvi and Lefohn, "Sample Distribution Shadow Maps", I3D
// 2011, sections 4.1 and 4.2: the depth histogram and the per-partition light-space bounds). Footprint floats are
// compared as uints through orderedBits, which keeps their order for both signs. Each pixel also counts, per light, in
// its cell of the occupancy grid of its depth's octave (shadows::OccupancyGrid), in the buffer directly: the cells a
// workgroup touches are few, and integer counts add up the same in any order.
#include "constants.glsl"
// The storage block DepthHistogram (`histogram`: per bin, the count and per light the orderedBits of the footprint's
// min x, min y, max x, max y; then the occupancy counts, light, octave, row, column) and the uniform block
// DepthHistogramFrame (`frame`), generated from their C++ declarations with the lengths PENUMBRA_BINS,
// PENUMBRA_LIGHTS, PENUMBRA_BIN_FOOTPRINTS, PENUMBRA_OCCUPANCY and PENUMBRA_OCCUPANCY_GRIDS (DepthReduction.cpp).
#include "depth_reduction_blocks.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

const uint kBins = PENUMBRA_BINS;
const uint kStepsPerOctave = PENUMBRA_STEPS_PER_OCTAVE;
const int kLights = PENUMBRA_LIGHTS;
const uint kCells = PENUMBRA_OCCUPANCY_CELLS;
const uint kOctaves = PENUMBRA_OCCUPANCY_OCTAVES;
// Each invocation reduces kPixels x kPixels pixels.
const uint kPixels = PENUMBRA_PIXELS_PER_INVOCATION;

layout(binding = 0) uniform sampler2D depth;

shared uint groupCount[kBins];
shared uint groupFootprints[kBins * PENUMBRA_BIN_FOOTPRINTS];

uint orderedBits(float f)
{
    const uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}

// shadows::depthHistogramBin.
uint binOf(float viewDepth)
{
    int exponent;
    const float mantissa = frexp(viewDepth, exponent);
    const int step = int((2.0 * mantissa - 1.0) * float(kStepsPerOctave));
    const int bin = (exponent - 1 - frame.firstOctave) * int(kStepsPerOctave) + step;
    return uint(clamp(bin, 0, int(kBins) - 1));
}

// shadows::occupancyOctave.
uint occupancyOctave(uint bin)
{
    const uint skipped = kBins / kStepsPerOctave - kOctaves;
    return max(bin / kStepsPerOctave, skipped) - skipped;
}

// The cell index of light-space x, y in light l's grid of its octave.
uint occupancyCell(int l, uint octave, vec2 light)
{
    const uint grid = uint(l) * kOctaves + octave;
    const vec4 g = frame.occupancyGrids[grid];
    const uvec2 cell = uvec2(clamp(ivec2(floor((light - g.xy) * g.z)), ivec2(0), ivec2(kCells - 1u)));
    return (grid * kCells + cell.y) * kCells + cell.x;
}

// An invocation's run of samples in one bin: their count and per light the footprint, merged into the group's with
// one atomic each when the bin changes rather than one per sample (neighbouring pixels mostly share a bin); and per
// light the run of samples in one occupancy cell, added to the buffer when the cell changes.
struct Run {
    uint bin;
    uint count;
    uvec4 footprint[kLights];
    uint cell[kLights];
    uint cellCount[kLights];
};

void flushBin(inout Run run)
{
    if (run.count == 0u)
        return;
    atomicAdd(groupCount[run.bin], run.count);
    for (int l = 0; l < frame.lightCount; ++l) {
        const uint at = (run.bin * uint(kLights) + uint(l)) * 4u;
        atomicMin(groupFootprints[at], run.footprint[l].x);
        atomicMin(groupFootprints[at + 1u], run.footprint[l].y);
        atomicMax(groupFootprints[at + 2u], run.footprint[l].z);
        atomicMax(groupFootprints[at + 3u], run.footprint[l].w);
    }
    run.count = 0u;
}

void flushCell(inout Run run, int l)
{
    if (run.cellCount[l] != 0u)
        atomicAdd(histogram.occupancy[run.cell[l]], run.cellCount[l]);
    run.cellCount[l] = 0u;
}

void count(inout Run run, const vec3 position, float viewDepth)
{
    const uint b = binOf(viewDepth);
    if (b != run.bin) {
        flushBin(run);
        run.bin = b;
    }
    ++run.count;
    for (int l = 0; l < frame.lightCount; ++l) {
        const vec2 light = vec2(dot(position, frame.lightRight[l].xyz), dot(position, frame.lightUp[l].xyz));
        const uint cell = occupancyCell(l, occupancyOctave(b), light);
        if (cell != run.cell[l]) {
            flushCell(run, l);
            run.cell[l] = cell;
        }
        ++run.cellCount[l];
        const uvec2 bits = uvec2(orderedBits(light.x), orderedBits(light.y));
        run.footprint[l] = run.count == 1u ? uvec4(bits, bits)
                                           : uvec4(min(run.footprint[l].xy, bits), max(run.footprint[l].zw, bits));
    }
}

void main()
{
    for (uint b = gl_LocalInvocationIndex; b < kBins; b += 256u) {
        groupCount[b] = 0u;
        for (uint k = 0u; k < 4u * uint(frame.lightCount); ++k)
            groupFootprints[b * 4u * uint(kLights) + k] = k % 4u < 2u ? 0xffffffffu : 0u;
    }
    Run run;
    run.bin = kBins;
    run.count = 0u;
    for (int l = 0; l < kLights; ++l) {
        run.footprint[l] = uvec4(0u);
        run.cell[l] = 0u;
        run.cellCount[l] = 0u;
    }
    barrier();
    const ivec2 size = textureSize(depth, 0);
    for (uint i = 0u; i < kPixels * kPixels; ++i) {
        const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy * kPixels + uvec2(i % kPixels, i / kPixels));
        if (!all(lessThan(pixel, size)))
            continue;
        const float d = texelFetch(depth, pixel, 0).r;
        // The clear value is the background: nothing drawn there.
        if (d == float(PENUMBRA_CLEAR_DEPTH))
            continue;
        const vec2 ndc = penumbraFragCoordToNdc(vec2(pixel) + 0.5, frame.targetSize.xy);
        const vec4 world = frame.clipToWorld * vec4(ndc, penumbraWindowDepthToNdc(d), 1.0);
        const vec3 position = world.xyz / world.w;
        const float viewDepth = dot(position - frame.cameraPosition.xyz, frame.cameraForward.xyz);
        if (viewDepth > 0.0 && viewDepth < frame.shadowFar)
            count(run, position, viewDepth);
    }
    flushBin(run);
    for (int l = 0; l < frame.lightCount; ++l)
        flushCell(run, l);
    barrier();
    for (uint b = gl_LocalInvocationIndex; b < kBins; b += 256u) {
        if (groupCount[b] == 0u)
            continue;
        atomicAdd(histogram.bins[b].count, groupCount[b]);
        for (int l = 0; l < frame.lightCount; ++l) {
            const uint at = (b * uint(kLights) + uint(l)) * 4u;
            const uint k = uint(l) * 4u;
            atomicMin(histogram.bins[b].footprints[k], groupFootprints[at]);
            atomicMin(histogram.bins[b].footprints[k + 1u], groupFootprints[at + 1u]);
            atomicMax(histogram.bins[b].footprints[k + 2u], groupFootprints[at + 2u]);
            atomicMax(histogram.bins[b].footprints[k + 3u], groupFootprints[at + 3u]);
        }
    }
}
