#pragma once

// Small compute scenes, each a write followed by a read of another kind: what ComputeTest checks on every
// configuration with every validation message failing the test, and what HazardTest runs with the list's barriers
// suppressed to show that Vulkan's synchronization validation reports the hazard each barrier prevents.

#include "penumbra/rhi/Device.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace penumbra::testing {

// Every scene records into `list` and submits; with `suppressBarriers` the list records no derived barrier.
struct SceneOptions {
    bool suppressBarriers = false;
    // storageImageSum binds its image and sum with one binding set instead of single bind calls.
    bool bindingSet = false;
    // ... and its pipelines list the set's layout (ComputePipelineDesc::bindingSetLayouts).
    bool listedLayout = false;
};

// An inclusive prefix sum of `values` (at most 1024) in one workgroup of 256 invocations with shared memory, copied
// into a Readback buffer: compute write -> copy read. Recorded under labels (pushLabel, insertLabel).
std::vector<std::uint32_t> prefixSum(rhi::Device& device, const std::vector<std::uint32_t>& values,
                                     const SceneOptions& options = {});

// A 32x32 picture with a horizontal red ramp is rendered, then a dispatch samples it and counts each red value in a
// 256-bin histogram: render target -> compute read. `picture` receives the rendered picture's red bytes.
struct Histogram {
    std::uint32_t total = 0;
    std::array<std::uint32_t, 256> bins{};
    std::vector<std::uint8_t> red; // the rendered picture's red channel, row by row
};
Histogram pictureHistogram(rhi::Device& device, const SceneOptions& options = {});

// A dispatch writes a triangle's vertices and its draw arguments, then a pass draws it into a 16x16 target, with
// drawIndirect (`indirect`) or draw: compute write -> indirect and vertex reads. Returns the picture's red bytes.
std::vector<std::uint8_t> computedTriangle(rhi::Device& device, bool indirect, const SceneOptions& options = {});

// A dispatch writes dispatch arguments (5, 1, 1), dispatchIndirect runs 5 workgroups of 4 invocations that count
// themselves: compute write -> indirect read. Returns the count.
std::uint32_t indirectInvocations(rhi::Device& device, const SceneOptions& options = {});

// A dispatch stores a 16x16 RGBA8 storage image (red = x), the next loads it and sums the red bytes: compute write ->
// compute read. Returns the sum and the image's red bytes as copyTextureToBuffer reads them back.
struct ImageSum {
    std::uint32_t red = 0;
    std::vector<std::uint8_t> image;
};
ImageSum storageImageSum(rhi::Device& device, const SceneOptions& options = {});

} // namespace penumbra::testing
