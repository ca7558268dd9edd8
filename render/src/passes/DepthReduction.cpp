#include "DepthReduction.hpp"

#include "penumbra/shaders/ShaderLibrary.hpp"
#include "penumbra/shadows/LightBasis.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <glm/matrix.hpp>
#include <span>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kLights = shadows::maxShadowedDirectionalLights;
constexpr std::uint32_t kDepthHistogramBinding = 1;
constexpr std::uint32_t kDepthHistogramFrameBinding = 2;
// The lengths of the histogram's arrays, PENUMBRA_BINS and PENUMBRA_BIN_FOOTPRINTS in depth_reduction.comp.
constexpr shaders::ShaderConstant kDepthBinsLength{"BINS", shadows::kDepthHistogramBins};
constexpr shaders::ShaderConstant kDepthBinFootprintsLength{"BIN_FOOTPRINTS", 4 * kLights};
constexpr std::uint32_t kGridCells = shadows::kOccupancyCells * shadows::kOccupancyCells;
constexpr shaders::ShaderConstant kOccupancyLength{"OCCUPANCY", kLights* shadows::kOccupancyOctaves* kGridCells};

// One bin of the storage block DepthHistogram (std430): the count, then per light the ordered bits of the
// footprint's min x, min y, max x, max y (flat uints: the shader's atomics take scalars).
struct GpuBin {
    std::uint32_t count;
    std::array<std::uint32_t, 4 * kLights> footprints;
};
constexpr std::array kGpuBinFields{PENUMBRA_SHADER_FIELD(GpuBin, count),
                                   PENUMBRA_SHADER_FIELD(GpuBin, footprints, kDepthBinFootprintsLength)};
constexpr shaders::ShaderStruct kGpuBinStruct{"Bin", sizeof(GpuBin), kGpuBinFields};

// The storage block DepthHistogram: the bins, then the occupancy grids' counts (light, octave, row, column).
struct GpuHistogram {
    std::array<GpuBin, shadows::kDepthHistogramBins> bins;
    std::array<std::uint32_t, kLights * shadows::kOccupancyOctaves * kGridCells> occupancy;
};
constexpr std::array kGpuHistogramFields{PENUMBRA_SHADER_STRUCT_FIELD(GpuHistogram, bins, kGpuBinStruct,
                                                                      kDepthBinsLength),
                                         PENUMBRA_SHADER_FIELD(GpuHistogram, occupancy, kOccupancyLength)};
constexpr shaders::ShaderStruct kGpuHistogramBlock{"DepthHistogram", sizeof(GpuHistogram), kGpuHistogramFields};
static_assert(shaders::matchesLayout(kGpuHistogramBlock, shaders::BlockLayout::Std430));

constexpr std::uint32_t kGroupSize = 16; // the shader's local_size_x and _y
// Each invocation reduces a square of pixels and merges runs of samples in one bin or occupancy cell before any atomic:
// 4 x 4 (docs/notes/2026-12-07-depth-fit-occupancy.md, "Cost after the fit and the reduction were made cheaper").
constexpr std::uint32_t kPixelsPerInvocation = 4;
constexpr std::uint32_t kGroupPixels = kGroupSize * kPixelsPerInvocation;

rhi::ShaderSource depthReductionShader(const rhi::Device& device)
{
    const auto clear = static_cast<std::int64_t>(device.conventions().clearDepth());
    rhi::ShaderSource source =
        shaders::load("depth_reduction.comp", {{"CLEAR_DEPTH", clear},
                                               {"STEPS_PER_OCTAVE", shadows::kDepthHistogramStepsPerOctave},
                                               {"OCCUPANCY_CELLS", shadows::kOccupancyCells},
                                               {"OCCUPANCY_OCTAVES", shadows::kOccupancyOctaves},
                                               {"PIXELS_PER_INVOCATION", kPixelsPerInvocation}});
    source.includes.push_back(
        {"depth_reduction_blocks.glsl",
         shaders::storageBlockGlsl(kGpuHistogramBlock, kDepthHistogramBinding, "histogram",
                                   shaders::BlockAccess::ReadWrite) +
             shaders::uniformBlockGlsl(kDepthHistogramFrameBlock, kDepthHistogramFrameBinding, "frame")});
    return source;
}

// What the buffer holds before the dispatch: no samples, every footprint empty (min above max). On the heap: the
// occupancy grids make it half a megabyte.
std::unique_ptr<GpuHistogram> emptyHistogram()
{
    GpuBin empty{};
    for (std::uint32_t k = 0; k < empty.footprints.size(); ++k)
        empty.footprints[k] = k % 4 < 2 ? 0xffffffffu : 0u;
    auto histogram = std::make_unique<GpuHistogram>();
    histogram->bins.fill(empty);
    histogram->occupancy.fill(0u);
    return histogram;
}

// depth_reduction.comp's orderedBits undone.
float fromOrderedBits(std::uint32_t bits)
{
    const std::uint32_t u = (bits & 0x80000000u) != 0 ? bits & 0x7fffffffu : ~bits;
    float f = 0.0f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

// The bytes of the block that `lights` lights use: the bins, then their occupancy grids (the last lights' are not
// cleared, dispatched over or read).
std::size_t usedBytes(std::size_t lights)
{
    return offsetof(GpuHistogram, occupancy) + lights * shadows::kOccupancyOctaves * kGridCells * sizeof(std::uint32_t);
}

} // namespace

DepthReduction::DepthReduction(rhi::Device& device)
{
    const std::unique_ptr<rhi::Shader> shader = device.createShader(depthReductionShader(device));
    pipeline_ = device.createComputePipeline({.compute = shader.get(),
                                              .uniformLayouts = {shaders::uniformLayout(kDepthHistogramFrameBlock)},
                                              .storageLayouts = {shaders::storageLayout(kGpuHistogramBlock)},
                                              .debugName = "depth reduction"});
    sampler_ = device.createSampler(
        {.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest, .debugName = "depth reduction"});
    bins_ = device.createBuffer(
        {.size = sizeof(GpuHistogram), .usage = rhi::BufferUsage::Storage, .debugName = "depth reduction histogram"});
    const std::unique_ptr<GpuHistogram> empty = emptyHistogram();
    const std::span<const std::byte> emptyBytes = std::as_bytes(std::span(empty.get(), 1));
    empty_.assign(emptyBytes.begin(), emptyBytes.end());
    frame_ = device.createBuffer({.size = sizeof(DepthHistogramFrame),
                                  .usage = rhi::BufferUsage::Uniform,
                                  .debugName = "depth reduction frame"});
}

void DepthReduction::record(rhi::CommandList& commands, const rhi::Texture& depth, const LitFrameUniforms& frame,
                            std::span<const glm::vec3> lights, float shadowFar)
{
    const rhi::TextureDesc& size = depth.desc();
    DepthHistogramFrame block;
    // Inverted in double, as the screen-space collection's: the positions lose no more than the depth's precision.
    block.clipToWorld = glm::mat4(glm::inverse(glm::dmat4(frame.viewProjection)));
    block.cameraPosition = frame.cameraPosition;
    block.cameraForward = frame.cameraForward;
    lights_.assign(lights.begin(), lights.begin() + std::min<std::size_t>(lights.size(), kLights));
    firstOctave_ = shadows::depthHistogramFirstOctave(shadowFar);
    grids_.assign(lights_.size(), {});
    for (std::size_t l = 0; l < lights_.size(); ++l) {
        const shadows::LightBasis basis = shadows::lightBasis(lights_[l]);
        block.lightRight[l] = glm::vec4(basis.right, 0.0f);
        block.lightUp[l] = glm::vec4(basis.up, 0.0f);
        const glm::vec2 camera = glm::vec2(basis.toLight(glm::vec3(frame.cameraPosition)));
        for (std::uint32_t o = 0; o < shadows::kOccupancyOctaves; ++o) {
            grids_[l].push_back(shadows::occupancyGridAbout(firstOctave_, o, camera));
            const shadows::OccupancyGrid& grid = grids_[l].back();
            block.occupancyGrids[l * shadows::kOccupancyOctaves + o] =
                glm::vec4(grid.origin, 1.0f / grid.cellSize, 0.0f);
        }
    }
    block.targetSize = glm::vec4(static_cast<float>(size.width), static_cast<float>(size.height), 0.0f, 0.0f);
    block.shadowFar = shadowFar;
    block.firstOctave = firstOctave_;
    block.lightCount = static_cast<std::int32_t>(lights_.size());
    frame_->writeObject(block);
    bins_->write(0, std::span<const std::byte>(empty_).first(usedBytes(lights_.size())));
    commands.bindComputePipeline(*pipeline_);
    commands.bindTexture(0, depth, *sampler_);
    commands.bindStorageBuffer(kDepthHistogramBinding, *bins_, 0, bins_->desc().size);
    commands.bindUniformBuffer(kDepthHistogramFrameBinding, *frame_, 0, sizeof(DepthHistogramFrame));
    commands.dispatch((size.width + kGroupPixels - 1) / kGroupPixels, (size.height + kGroupPixels - 1) / kGroupPixels);
    recorded_ = true;
}

std::optional<shadows::DepthHistogram> DepthReduction::read()
{
    if (!recorded_)
        return std::nullopt;
    recorded_ = false;
    const auto read = std::make_unique<GpuHistogram>();
    bins_->read(0, std::as_writable_bytes(std::span(read.get(), 1)).first(usedBytes(lights_.size())));
    shadows::DepthHistogram histogram;
    histogram.firstOctave = firstOctave_;
    histogram.lightDirections = lights_;
    histogram.occupancy = grids_;
    for (std::size_t l = 0; l < grids_.size(); ++l)
        for (std::size_t o = 0; o < shadows::kOccupancyOctaves; ++o) {
            const auto first = read->occupancy.begin() +
                               static_cast<std::ptrdiff_t>((l * shadows::kOccupancyOctaves + o) * kGridCells);
            histogram.occupancy[l][o].counts.assign(first, first + kGridCells);
        }
    for (const GpuBin& gpu : read->bins) {
        shadows::DepthHistogramBin bin;
        bin.count = gpu.count;
        // Footprints of lights not measured keep DepthHistogramBin's zeros (the planner reads the measured ones).
        for (std::size_t l = 0; l < lights_.size() && bin.count > 0; ++l)
            bin.footprints[l] = {fromOrderedBits(gpu.footprints[4 * l]), fromOrderedBits(gpu.footprints[4 * l + 1]),
                                 fromOrderedBits(gpu.footprints[4 * l + 2]),
                                 fromOrderedBits(gpu.footprints[4 * l + 3])};
        histogram.bins.push_back(bin);
    }
    return histogram;
}

} // namespace penumbra::render
