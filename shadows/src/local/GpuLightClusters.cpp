#include "penumbra/shadows/GpuLightClusters.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <bit>
#include <cstring>
#include <fmt/format.h>

namespace penumbra::shadows {
namespace {

constexpr std::uint32_t kClusterGroupSize = 64; // light_clusters.comp's local_size_x of the count and write stages

constexpr std::uint32_t kClusterGridBinding = 0;
constexpr std::uint32_t kClusterLightBoundsBinding = 1;
constexpr std::uint32_t kClusterCountsBinding = 2;

// The pass's storage blocks. Every member name is distinct across the blocks (Mesa's GLSL compiler, see
// GpuCasterCulling).
constexpr std::array kClusterGridFields{PENUMBRA_SHADER_FIELD(ClusterGridHeader, gridSize),
                                        PENUMBRA_SHADER_FIELD(ClusterGridHeader, dataLayout),
                                        PENUMBRA_SHADER_FIELD(ClusterGridHeader, view),
                                        shaders::runtimeArrayField<float>("edges", sizeof(ClusterGridHeader))};
constexpr shaders::ShaderStruct kClusterGridBlock{"ClusterGrid", sizeof(ClusterGridHeader), kClusterGridFields};
constexpr std::array kClusterLightBoundsFields{
    shaders::runtimeStructArrayField<ClusterLightBound>("lights", 0, kClusterLightBoundStruct)};
constexpr shaders::ShaderStruct kClusterLightBoundsBlock{"ClusterLightBounds", 0, kClusterLightBoundsFields};
constexpr std::array kClusterCountsFields{shaders::runtimeArrayField<std::uint32_t>("clusterCounts", 0)};
constexpr shaders::ShaderStruct kClusterCountsBlock{"ClusterCounts", 0, kClusterCountsFields};
static_assert(shaders::matchesLayout(kClusterGridBlock, shaders::BlockLayout::Std430) &&
              shaders::matchesLayout(kClusterLightBoundsBlock, shaders::BlockLayout::Std430) &&
              shaders::matchesLayout(kClusterCountsBlock, shaders::BlockLayout::Std430));

// The storage blocks generated from their C++ declarations, and the images the lists are written to.
std::string clusterBlocksGlsl()
{
    using shaders::BlockAccess;
    return shaders::storageBlockGlsl(kClusterGridBlock, kClusterGridBinding, "grid", BlockAccess::ReadOnly) +
           shaders::storageBlockGlsl(kClusterLightBoundsBlock, kClusterLightBoundsBinding, "lightBounds",
                                     BlockAccess::ReadOnly) +
           shaders::storageBlockGlsl(kClusterCountsBlock, kClusterCountsBinding, "counts", BlockAccess::ReadWrite) +
           "layout(binding = 3, rgba32f) uniform writeonly image2D clusterRanges;\n"
           "layout(binding = 4, r32f) uniform writeonly image2D lightIndices;\n";
}

std::unique_ptr<rhi::ComputePipeline> clusterPipeline(rhi::Device& device, int stage, const char* name)
{
    rhi::ShaderSource source = shaders::load("light_clusters.comp", {{"STAGE", stage}});
    source.includes.push_back({"light_cluster_blocks.glsl", clusterBlocksGlsl()});
    const std::unique_ptr<rhi::Shader> shader = device.createShader(source);
    return device.createComputePipeline(
        {.compute = shader.get(),
         .storageLayouts = {shaders::storageLayout(kClusterGridBlock), shaders::storageLayout(kClusterLightBoundsBlock),
                            shaders::storageLayout(kClusterCountsBlock)},
         .debugName = name});
}

void checkDataTexture(const rhi::Texture& texture, rhi::Format format, std::uint64_t texels, const char* what)
{
    const rhi::TextureDesc& d = texture.desc();
    if (d.format != format || !std::has_single_bit(d.width) || std::uint64_t(d.width) * d.height < texels)
        throw rhi::Error(fmt::format("GpuLightClusters: the {} texture '{}' is {} x {} of format {}; it needs format "
                                     "{}, a power-of-two width and room for {} texels",
                                     what, d.debugName, d.width, d.height, rhi::formatName(d.format),
                                     rhi::formatName(format), texels));
}

} // namespace

GpuLightClusters::GpuLightClusters(rhi::Device& device)
    : device_(device), pipelines_{clusterPipeline(device, 0, "light cluster counts"),
                                  clusterPipeline(device, 1, "light cluster sums"),
                                  clusterPipeline(device, 2, "light cluster lists")}
{
}

void GpuLightClusters::reserve(std::uint64_t gridBytes, std::uint64_t lights, std::uint64_t clusters)
{
    const auto ensure = [&](std::unique_ptr<rhi::Buffer>& buffer, std::uint64_t size, const char* name) {
        if (!buffer || buffer->desc().size < size)
            buffer = device_.createBuffer({.size = size, .usage = rhi::BufferUsage::Storage, .debugName = name});
    };
    ensure(grid_, gridBytes, "light cluster grid");
    ensure(lights_, std::max<std::uint64_t>(lights, 1) * sizeof(ClusterLightBound), "light cluster bounds");
    ensure(counts_, 2 * clusters * sizeof(std::uint32_t), "light cluster counts");
}

void GpuLightClusters::record(rhi::CommandList& commands, const LightClusterInputs& inputs, const rhi::Texture& ranges,
                              const rhi::Texture& indices)
{
    const LightClusterUniforms& g = inputs.grid;
    const std::uint64_t clusters = std::uint64_t(g.tilesX) * g.tilesY * g.slices;
    checkDataTexture(ranges, rhi::Format::RGBA32F, clusters, "cluster");
    checkDataTexture(indices, rhi::Format::R32F, std::max<std::uint64_t>(inputs.entryBound, 1), "light index");
    if (ranges.desc().width != indices.desc().width)
        throw rhi::Error("GpuLightClusters: the cluster and light index textures differ in width");
    ClusterGridHeader header;
    header.gridSize = {int(g.tilesX), int(g.tilesY), int(g.slices), int(inputs.lights.size())};
    header.dataLayout.x = std::countr_zero(ranges.desc().width);
    header.view = {inputs.tanHalf, kClusterBoxMargin, 0.0f};
    const std::size_t edges = inputs.edgesX.size() + inputs.edgesY.size() + inputs.depths.size();
    gridBytes_.resize(sizeof header + edges * sizeof(float));
    std::byte* out = gridBytes_.data();
    std::memcpy(out, &header, sizeof header);
    out += sizeof header;
    for (const std::vector<float>* part : {&inputs.edgesX, &inputs.edgesY, &inputs.depths}) {
        std::memcpy(out, part->data(), part->size() * sizeof(float));
        out += part->size() * sizeof(float);
    }
    reserve(gridBytes_.size(), inputs.lights.size(), clusters);
    grid_->write(0, gridBytes_);
    if (!inputs.lights.empty())
        lights_->write(0, std::as_bytes(std::span(inputs.lights)));

    commands.bindStorageBuffer(kClusterGridBinding, *grid_, 0, gridBytes_.size());
    commands.bindStorageBuffer(kClusterLightBoundsBinding, *lights_, 0, lights_->desc().size);
    commands.bindStorageBuffer(kClusterCountsBinding, *counts_, 0, 2 * clusters * sizeof(std::uint32_t));
    commands.bindStorageTexture(3, ranges);
    commands.bindStorageTexture(4, indices);
    const auto groups = static_cast<std::uint32_t>((clusters + kClusterGroupSize - 1) / kClusterGroupSize);
    commands.bindComputePipeline(*pipelines_[0]);
    commands.dispatch(groups);
    commands.bindComputePipeline(*pipelines_[1]);
    commands.dispatch(1);
    commands.bindComputePipeline(*pipelines_[2]);
    commands.dispatch(groups);
}

} // namespace penumbra::shadows
