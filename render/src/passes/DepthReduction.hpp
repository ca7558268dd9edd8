#pragma once

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/DepthFit.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace penumbra::render {

// The shadowed directional lights the depth reduction measures, PENUMBRA_LIGHTS in depth_reduction.comp.
inline constexpr shaders::ShaderConstant kDepthReductionLights{"LIGHTS", shadows::maxShadowedDirectionalLights};
// The occupancy grids, one per light and octave (shadows::OccupancyGrid), PENUMBRA_OCCUPANCY_GRIDS.
inline constexpr shaders::ShaderConstant kOccupancyGrids{
    "OCCUPANCY_GRIDS", shadows::maxShadowedDirectionalLights* shadows::kOccupancyOctaves};

// The block DepthHistogramFrame of shaders/depth_reduction.comp, std140: how a pixel becomes a world position, view
// depth and light-space x, y.
struct DepthHistogramFrame {
    glm::mat4 clipToWorld{1.0f};
    glm::vec4 cameraPosition{0.0f};
    glm::vec4 cameraForward{0.0f};
    std::array<glm::vec4, shadows::maxShadowedDirectionalLights> lightRight{};
    std::array<glm::vec4, shadows::maxShadowedDirectionalLights> lightUp{};
    // Per light, per occupancy octave: the grid's origin x, y and 1 / its cell size (a power of two: exact).
    std::array<glm::vec4, shadows::maxShadowedDirectionalLights * shadows::kOccupancyOctaves> occupancyGrids{};
    glm::vec4 targetSize{0.0f}; // width, height in pixels
    float shadowFar = 0.0f; // samples at or past it are not counted
    std::int32_t firstOctave = 0; // shadows::depthHistogramFirstOctave(shadowFar)
    std::int32_t lightCount = 0;
};

inline constexpr std::array kDepthHistogramFrameFields{
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, clipToWorld),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, cameraPosition),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, cameraForward),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, lightRight, kDepthReductionLights),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, lightUp, kDepthReductionLights),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, occupancyGrids, kOccupancyGrids),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, targetSize),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, shadowFar),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, firstOctave),
    PENUMBRA_SHADER_FIELD(DepthHistogramFrame, lightCount),
};
inline constexpr shaders::ShaderStruct kDepthHistogramFrameBlock{"DepthHistogramFrame", sizeof(DepthHistogramFrame),
                                                                 kDepthHistogramFrameFields};
static_assert(shaders::matchesLayout(kDepthHistogramFrameBlock, shaders::BlockLayout::Std140));

// The depth fit's reduction (shaders/depth_reduction.comp): the histogram of the view depths of the pixels a
// single-sampled depth texture holds, with each bin's light-space footprint and the occupancy grids per shadowed
// directional light (shadows::DepthHistogram), into a storage buffer. The renderer reads it after the frame's
// submission (which already waits for the GPU), so the next frame plans with it and none waits for it.
class DepthReduction {
public:
    explicit DepthReduction(rhi::Device& device);

    // Resets the buffer and records the dispatch over `depth` (single-sampled, sampled, the frame's lit depth) seen
    // through `frame`'s view (its view-projection, camera position and forward), for the shadowed directional lights
    // `lights` (directions, in slot order; at most maxShadowedDirectionalLights) up to view depth shadowFar.
    void record(rhi::CommandList& commands, const rhi::Texture& depth, const LitFrameUniforms& frame,
                std::span<const glm::vec3> lights, float shadowFar);
    // After the submission: the histogram; nullopt where nothing was recorded since the last read.
    std::optional<shadows::DepthHistogram> read();
    // The storage buffer record()'s dispatch writes and read() reads.
    const rhi::Buffer& histogram() const { return *bins_; }

private:
    std::unique_ptr<rhi::ComputePipeline> pipeline_;
    std::unique_ptr<rhi::Sampler> sampler_;
    std::unique_ptr<rhi::Buffer> bins_;
    std::unique_ptr<rhi::Buffer> frame_;
    std::vector<std::byte> empty_; // what the buffer holds before the dispatch
    int firstOctave_ = 0;
    std::vector<glm::vec3> lights_;
    std::vector<std::vector<shadows::OccupancyGrid>> grids_; // per light, the occupancy grids, counts empty
    bool recorded_ = false;
};

} // namespace penumbra::render
