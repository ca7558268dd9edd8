#pragma once

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/LightClusters.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace penumbra::shadows {

// ClusterLightBound as a storage element.
inline constexpr std::array kClusterLightBoundFields{
    PENUMBRA_SHADER_FIELD(ClusterLightBound, bound), PENUMBRA_SHADER_FIELD(ClusterLightBound, reach),
    PENUMBRA_SHADER_FIELD(ClusterLightBound, axis),  PENUMBRA_SHADER_FIELD(ClusterLightBound, cone),
    PENUMBRA_SHADER_FIELD(ClusterLightBound, tiles), PENUMBRA_SHADER_FIELD(ClusterLightBound, slices),
};
inline constexpr shaders::ShaderStruct kClusterLightBoundStruct{"ClusterLightBound", sizeof(ClusterLightBound),
                                                                kClusterLightBoundFields};
static_assert(shaders::matchesLayout(kClusterLightBoundStruct, shaders::BlockLayout::Std430, true));

// The fixed part of the storage block ClusterGrid, before its edges (LightClusterInputs' edgesX, edgesY, depths).
struct ClusterGridHeader {
    glm::ivec4 gridSize{0}; // tiles across, tiles down, slices, lights
    glm::ivec4 dataLayout{0}; // x: log2 of the data textures' width
    glm::vec4 view{0.0f}; // tangents of the half fields of view across and down; the boxes' margin
};

// The clustered light lists built on the GPU (shaders/light_clusters.comp) from the bounds buildLightClusters
// tests: one dispatch counts each cluster's lights, one sums the counts into each cluster's first entry (in cluster
// order) and one writes each cluster's lights, ascending. The lists are written as the lit pass reads the CPU's
// (render::LocalLightTextures): texel c of `ranges` (RGBA32F) holds cluster c's first entry and length as floats,
// texel e of `indices` (R32F) entry e's light; texel t of either is (t mod width, t / width).
class GpuLightClusters {
public:
    explicit GpuLightClusters(rhi::Device& device);

    // Uploads `inputs` and records the dispatches into `ranges` and `indices`: storage textures of one power-of-two
    // width, ranges with a texel for every cluster, indices for inputs.entryBound entries. Throws rhi::Error where
    // they are not.
    void record(rhi::CommandList& commands, const LightClusterInputs& inputs, const rhi::Texture& ranges,
                const rhi::Texture& indices);

private:
    void reserve(std::uint64_t gridBytes, std::uint64_t lights, std::uint64_t clusters);

    rhi::Device& device_;
    std::array<std::unique_ptr<rhi::ComputePipeline>, 3> pipelines_; // count, sum, write
    std::unique_ptr<rhi::Buffer> grid_;
    std::unique_ptr<rhi::Buffer> lights_;
    std::unique_ptr<rhi::Buffer> counts_;
    std::vector<std::byte> gridBytes_; // what record() uploads, kept from frame to frame
};

} // namespace penumbra::shadows
