#include "penumbra/shadows/GpuCasterCulling.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::shadows {
namespace {

// The uniform block at binding 0; the storage blocks follow it (bindingOf).
constexpr std::uint32_t kTilesBinding = 0;
constexpr std::array kCullingTilesFields{PENUMBRA_SHADER_FIELD(CullingTiles, casterCount),
                                         PENUMBRA_SHADER_FIELD(CullingTiles, tileCount),
                                         PENUMBRA_SHADER_FIELD(CullingTiles, batchCount),
                                         PENUMBRA_SHADER_FIELD(CullingTiles, firstTile),
                                         PENUMBRA_SHADER_FIELD(CullingTiles, tileSlots),
                                         PENUMBRA_SHADER_FIELD(CullingTiles, markWords),
                                         PENUMBRA_SHADER_FIELD(CullingTiles, chunkRuns),
                                         PENUMBRA_SHADER_STRUCT_FIELD(CullingTiles, volumes, kCasterVolumeStruct)};
constexpr shaders::ShaderStruct kCullingTilesBlock{"CullingTiles", sizeof(CullingTiles), kCullingTilesFields};
static_assert(shaders::matchesLayout(kCullingTilesBlock, shaders::BlockLayout::Std140));

// The pass's storage blocks' members. Every member name is distinct across the blocks:
// Mesa's GLSL compiler (22.3) takes an unsized array for another block's member of the same name and refuses to
// index it.
constexpr std::array kCullingCastersFields{
    shaders::runtimeStructArrayField<CullingCaster>("casters", 0, kCullingCasterStruct)};
constexpr std::array kInstanceTransformsFields{
    shaders::runtimeStructArrayField<InstanceTransform>("transforms", 0, kInstanceTransformStruct)};
constexpr std::array kCulledInstancesFields{
    shaders::runtimeStructArrayField<InstanceTransform>("instances", 0, kInstanceTransformStruct)};
constexpr std::array kCulledIndicesFields{shaders::runtimeArrayField<std::uint32_t>("indices", 0)};
constexpr std::array kCulledDrawsFields{shaders::runtimeStructArrayField<CulledDraw>("commands", 0, kCulledDrawStruct)};
constexpr std::array kCulledDrawCountsFields{shaders::runtimeArrayField<std::uint32_t>("counts", 0)};
constexpr std::array kCullingOrderFields{shaders::runtimeArrayField<std::uint32_t>("order", 0)};
constexpr std::array kCullingMarksFields{shaders::runtimeArrayField<std::uint32_t>("bits", 0)};

// The storage blocks, in binding order: block b at binding kTilesBinding + 1 + b.
enum CullingBlockIndex : std::uint32_t { kCasters, kTransforms, kInstances, kIndices, kDraws, kCounts, kOrder, kMarks };
constexpr std::uint32_t bindingOf(CullingBlockIndex block) { return kTilesBinding + 1 + block; }

// A block, its place, instance name and access.
struct CullingBlock {
    CullingBlockIndex index;
    shaders::ShaderStruct block;
    std::string_view instance;
    shaders::BlockAccess access;
};
constexpr std::array kCullingBlocks{
    CullingBlock{kCasters, {"CullingCasters", 0, kCullingCastersFields}, "casterList", shaders::BlockAccess::ReadOnly},
    CullingBlock{
        kTransforms, {"InstanceTransforms", 0, kInstanceTransformsFields}, "source", shaders::BlockAccess::ReadOnly},
    CullingBlock{kInstances, {"CulledInstances", 0, kCulledInstancesFields}, "culled", shaders::BlockAccess::WriteOnly},
    CullingBlock{
        kIndices, {"CulledIndices", 0, kCulledIndicesFields}, "culledIndices", shaders::BlockAccess::WriteOnly},
    CullingBlock{kDraws, {"CulledDraws", 0, kCulledDrawsFields}, "draws", shaders::BlockAccess::ReadWrite},
    CullingBlock{
        kCounts, {"CulledDrawCounts", 0, kCulledDrawCountsFields}, "drawCounts", shaders::BlockAccess::ReadWrite},
    CullingBlock{kOrder, {"CullingOrder", 0, kCullingOrderFields}, "casterOrder", shaders::BlockAccess::ReadOnly},
    CullingBlock{kMarks, {"CullingMarks", 0, kCullingMarksFields}, "marks", shaders::BlockAccess::ReadWrite},
};
static_assert([] {
    for (std::uint32_t i = 0; i < kCullingBlocks.size(); ++i)
        if (kCullingBlocks[i].index != i)
            return false;
    return kCullingBlocks.size() == kMarks + 1;
}());

// Tile t's bits of the marks: one per slot, in 32-bit words, two for each workgroup of 64 of the first dispatch.
std::uint32_t markWords(std::uint32_t tileSlots) { return (tileSlots + 63) / 64 * 2; }
static_assert(std::all_of(kCullingBlocks.begin(), kCullingBlocks.end(), [](const CullingBlock& b) {
    return shaders::matchesLayout(b.block, shaders::BlockLayout::Std430);
}));

// The pass's blocks generated from their C++ declarations, and the volume kinds.
std::string cullingBlocksGlsl()
{
    std::string text = fmt::format("#define PENUMBRA_VOLUME_FRUSTUM {}\n#define PENUMBRA_VOLUME_BEYOND_SPHERE {}\n"
                                   "#define PENUMBRA_VOLUME_BEYOND_SLICE {}\n#define PENUMBRA_CULLING_TILES {}\n"
                                   "#define PENUMBRA_CULLING_RUN_PLACES {}\n#define PENUMBRA_CULLING_CHUNK_RUNS {}\n",
                                   static_cast<int>(CasterVolumeKind::Frustum),
                                   static_cast<int>(CasterVolumeKind::CascadeBeyondSphere),
                                   static_cast<int>(CasterVolumeKind::CascadeBeyondSlice), kCullingTilesPerDispatch,
                                   kCullingRunPlaces, kCullingChunkRuns);
    text += shaders::uniformBlockGlsl(kCullingTilesBlock, kTilesBinding, "tiles");
    for (const CullingBlock& b : kCullingBlocks)
        text += shaders::storageBlockGlsl(b.block, bindingOf(b.index), b.instance, b.access);
    return text;
}

std::vector<rhi::UniformLayout> cullingStorageLayouts()
{
    std::vector<rhi::UniformLayout> layouts;
    for (const CullingBlock& b : kCullingBlocks)
        layouts.push_back(shaders::storageLayout(b.block));
    return layouts;
}

// The volume kinds a dispatch's tiles hold, as the test shader's variants tell them apart.
enum VolumeKinds : std::uint32_t { kFrustums = 1, kCascades = 2, kSlices = 4 };

std::uint32_t volumeKinds(std::span<const CasterVolume> volumes)
{
    std::uint32_t kinds = 0;
    for (const CasterVolume& volume : volumes)
        kinds |= volume.kind == CasterVolumeKind::Frustum
                     ? kFrustums
                     : (volume.kind == CasterVolumeKind::CascadeBeyondSlice ? kCascades | kSlices : kCascades);
    return kinds;
}

rhi::ShaderSource cullingShader(rhi::ShaderSource source)
{
    source.includes.push_back({"culling_blocks.glsl", cullingBlocksGlsl()});
    return source;
}

std::uint64_t roundUp(std::uint64_t value, std::uint64_t multiple)
{
    return (value + multiple - 1) / multiple * multiple;
}

// A caster's world box as the tests read it.
CullingCaster cullingCaster(const Bounds& box) { return {glm::vec4(box.min, 0.0f), glm::vec4(box.max, 0.0f)}; }

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& values)
{
    return std::as_bytes(std::span(values));
}

} // namespace

GpuCasterCulling::GpuCasterCulling(rhi::Device& device, std::uint32_t maxTilesPerDispatch, std::uint32_t chunkRuns)
    : device_(device), listsShader_(device.createShader(cullingShader(shaders::load("caster_culling_lists.comp")))),
      listsPipeline_(device.createComputePipeline({.compute = listsShader_.get(),
                                                   .uniformLayouts = {shaders::uniformLayout(kCullingTilesBlock)},
                                                   .storageLayouts = cullingStorageLayouts(),
                                                   .debugName = "caster culling lists"})),
      maxTilesPerDispatch_(std::max(maxTilesPerDispatch, 1u)), chunkRuns_(std::clamp(chunkRuns, 1u, kCullingChunkRuns))
{
    reserve(1, sizeof(CullingTiles), 1);
}

const rhi::ComputePipeline& GpuCasterCulling::testPipeline(std::uint32_t kinds)
{
    TestPipeline& test = testPipelines_.at(kinds);
    if (!test.pipeline) {
        test.shader = device_.createShader(
            cullingShader(shaders::load("caster_culling.comp", {{"CULL_FRUSTUMS", (kinds & kFrustums) != 0},
                                                                {"CULL_CASCADES", (kinds & kCascades) != 0},
                                                                {"CULL_SLICES", (kinds & kSlices) != 0}})));
        test.pipeline = device_.createComputePipeline({.compute = test.shader.get(),
                                                       .uniformLayouts = {shaders::uniformLayout(kCullingTilesBlock)},
                                                       .storageLayouts = cullingStorageLayouts(),
                                                       .debugName = "caster culling"});
    }
    return *test.pipeline;
}

// The instance lists hold tileSlots_ per tile; `volumeBytes` is the dispatches' blocks of the tiles buffer.
void GpuCasterCulling::reserve(std::uint64_t casters, std::uint64_t volumeBytes, std::uint64_t draws)
{
    using rhi::BufferUsage;
    const auto ensure = [&](std::unique_ptr<rhi::Buffer>& buffer, std::uint64_t size, BufferUsage usage,
                            const char* name) {
        if (!buffer || buffer->desc().size < size)
            buffer = device_.createBuffer({.size = size, .usage = usage, .debugName = name});
    };
    ensure(volumes_, volumeBytes, BufferUsage::Uniform, "culling tiles");
    ensure(casters_, casters * sizeof(CullingCaster), BufferUsage::Storage, "culling casters");
    ensure(transforms_, casters * sizeof(InstanceTransform), BufferUsage::Storage, "culling transforms");
    ensure(order_, (casters + batches_.batches.size() + 1) * sizeof(std::uint32_t), BufferUsage::Storage,
           "culling order");
    ensure(marks_,
           std::max<std::uint64_t>(std::uint64_t(tileCount_) * markWords(tileSlots_), 1) * sizeof(std::uint32_t),
           BufferUsage::Storage, "culling marks");
    const std::uint64_t slots = std::max<std::uint64_t>(std::uint64_t(tileCount_) * tileSlots_, 1);
    ensure(instances_, slots * sizeof(InstanceTransform), BufferUsage::Storage | BufferUsage::Vertex,
           "culled instances");
    ensure(indices_, slots * sizeof(std::uint32_t), BufferUsage::Storage, "culled indices");
    ensure(draws_, draws * sizeof(CulledDraw), BufferUsage::Storage | BufferUsage::Indirect, "culled draws");
    ensure(counts_, draws * sizeof(std::uint32_t), BufferUsage::Storage | BufferUsage::Indirect, "culled draw counts");
}

void GpuCasterCulling::record(rhi::CommandList& commands, std::span<const ShadowCaster> casters,
                              std::span<const Bounds> bounds, std::span<const CasterVolume> volumes,
                              const CasterChanges* changes)
{
    prepare(casters, bounds, volumes, changes);
    dispatch(commands);
}

void GpuCasterCulling::prepare(std::span<const ShadowCaster> casters, std::span<const Bounds> bounds,
                               std::span<const CasterVolume> volumes, const CasterChanges* changes)
{
    if (casters.size() != bounds.size())
        throw rhi::Error(
            fmt::format("GPU caster culling: {} casters, but {} caster bounds", casters.size(), bounds.size()));
    casterCount_ = static_cast<std::uint32_t>(casters.size());
    tileCount_ = static_cast<std::uint32_t>(volumes.size());
    groups_ = 0;
    uploaded_.clear();
    // The casters changed since those in storage were uploaded, where storage holds this list's.
    std::optional<std::vector<CasterRange>> changed;
    if (changes && resident_ && resident_->generation && resident_->casters == casterCount_)
        changed = changes->since(resident_->generation);
    if (!changed) {
        resident_.reset();
        std::vector<std::uint32_t>& all = scratch_.all;
        all.resize(casters.size());
        for (std::uint32_t i = 0; i < all.size(); ++i)
            all[i] = i;
        // The batches every tile draws, as the CPU path batches each tile's list (ShadowCasterDraws::draw).
        batches_ = batchByGroup(all, [&](std::uint32_t index) { return casters[index].drawGroup; });
    }
    if (casterCount_ == 0 || tileCount_ == 0)
        return;
    // A tile's slots start at a multiple of the binding offset alignment in both lists (4 and 48 bytes a slot).
    const rhi::Capabilities& caps = device_.capabilities();
    tileSlots_ = static_cast<std::uint32_t>(roundUp(casterCount_, std::max(caps.storageBufferOffsetAlignment / 4, 1u)));
    const std::uint64_t tileBytes = std::uint64_t(tileSlots_) * sizeof(InstanceTransform);
    if (tileBytes > caps.maxStorageBufferRange)
        throw rhi::Error(fmt::format("GPU caster culling: {} casters need {} MiB of instances per tile, beyond the "
                                     "device's storage range of {} MiB (maxStorageBufferRange); cull on the CPU "
                                     "(--culling cpu) or draw fewer casters",
                                     casterCount_, tileBytes >> 20, caps.maxStorageBufferRange >> 20));
    if (changed) {
        fillChanged(casters, bounds, *changed);
        uploaded_ = std::move(*changed);
    } else {
        fillCasters(casters, bounds);
        uploaded_ = {{0, casterCount_}};
    }
    fillDraws(casters);
    uploadTiles(volumes);
    resident_ = Resident{changes ? std::optional(changes->generation()) : std::nullopt, casterCount_};
}

// The casters' boxes, batches and transforms as the pass reads them.
void GpuCasterCulling::fillCasters(std::span<const ShadowCaster> casters, std::span<const Bounds> bounds)
{
    std::vector<CullingCaster>& culling = scratch_.casters;
    std::vector<InstanceTransform>& transforms = scratch_.transforms;
    culling.resize(casters.size());
    transforms.resize(casters.size());
    const auto batchCount = static_cast<std::uint32_t>(batches_.batches.size());
    for (std::uint32_t b = 0; b < batchCount; ++b) {
        const InstanceBatches::Batch& batch = batches_.batches[b];
        const ShadowCaster& first = casters[batches_.items[batch.first]];
        for (std::uint32_t k = batch.first; k < batch.first + batch.count; ++k) {
            const std::uint32_t i = batches_.items[k];
            if (!drawAlike(first, casters[i]))
                throw rhi::Error(fmt::format("shadow casters {} and {} share draw group {}, but draw differently "
                                             "(mesh, material or sides)",
                                             batches_.items[batch.first], i, first.drawGroup));
            culling[i] = cullingCaster(bounds[i]);
            transforms[i] = instanceTransform(casters[i].model);
        }
    }
}

void GpuCasterCulling::fillChanged(std::span<const ShadowCaster> casters, std::span<const Bounds> bounds,
                                   std::span<const CasterRange> changed)
{
    for (const CasterRange& range : changed)
        for (std::uint32_t i = range.first; i < range.first + range.count; ++i) {
            scratch_.casters[i] = cullingCaster(bounds[i]);
            scratch_.transforms[i] = instanceTransform(casters[i].model);
        }
}

void GpuCasterCulling::fillDraws(std::span<const ShadowCaster> casters)
{
    std::vector<CulledDraw>& draws = scratch_.draws;
    draws.clear();
    for (std::uint32_t t = 0; t < tileCount_; ++t)
        for (const InstanceBatches::Batch& batch : batches_.batches)
            draws.push_back({.indexCount = casters[batches_.items[batch.first]].indexCount});
}

void GpuCasterCulling::uploadCasters()
{
    for (const CasterRange& range : uploaded_) {
        casters_->write(range.first * sizeof(CullingCaster),
                        std::as_bytes(std::span(scratch_.casters).subspan(range.first, range.count)));
        transforms_->write(range.first * sizeof(InstanceTransform),
                           std::as_bytes(std::span(scratch_.transforms).subspan(range.first, range.count)));
    }
}

// One dispatch per group of tiles whose instance ranges fit one storage binding and whose volumes fit one
// CullingTiles (all tiles in one, unless there are more than 64 or the device's storage range is short of them); each
// group reads its own CullingTiles in the tiles buffer.
void GpuCasterCulling::uploadTiles(std::span<const CasterVolume> volumes)
{
    const rhi::Capabilities& caps = device_.capabilities();
    const std::uint64_t tileBytes = std::uint64_t(tileSlots_) * sizeof(InstanceTransform);
    groupTiles_ = static_cast<std::uint32_t>(std::min<std::uint64_t>(
        {tileCount_, maxTilesPerDispatch_, kCullingTilesPerDispatch, caps.maxStorageBufferRange / tileBytes}));
    blockBytes_ = roundUp(sizeof(CullingTiles), caps.uniformBufferOffsetAlignment);
    groups_ = (tileCount_ + groupTiles_ - 1) / groupTiles_;
    groupTests_.clear();
    const auto batchCount = static_cast<std::uint32_t>(batches_.batches.size());
    const rhi::Buffer* residentCasters = casters_.get();
    const rhi::Buffer* residentTransforms = transforms_.get();
    const rhi::Buffer* residentOrder = order_.get();
    reserve(casterCount_, groups_ * blockBytes_, std::uint64_t(tileCount_) * batchCount);
    // Buffers made anew hold none of the casters.
    const bool fresh =
        casters_.get() != residentCasters || transforms_.get() != residentTransforms || order_.get() != residentOrder;
    if (fresh)
        uploaded_ = {{0, casterCount_}};
    uploadCasters();
    // The batches' order changes only where everything is uploaded (a new batching, or fresh buffers).
    if (uploaded_.size() == 1 && uploaded_.front().first == 0 && uploaded_.front().count == casterCount_) {
        std::vector<std::uint32_t>& order = scratch_.order;
        order.assign(batches_.items.begin(), batches_.items.end());
        for (const InstanceBatches::Batch& batch : batches_.batches)
            order.push_back(batch.first);
        order.push_back(casterCount_);
        order_->write(0, bytesOf(order));
    }
    const std::vector<CulledDraw>& draws = scratch_.draws;
    draws_->write(0, bytesOf(draws));
    for (std::uint32_t g = 0; g < groups_; ++g) {
        const std::uint32_t first = g * groupTiles_, count = std::min(groupTiles_, tileCount_ - first);
        CullingTiles& block = scratch_.tiles;
        block.casterCount = casterCount_;
        block.tileCount = count;
        block.batchCount = batchCount;
        block.firstTile = first;
        block.tileSlots = tileSlots_;
        block.markWords = markWords(tileSlots_);
        block.chunkRuns = chunkRuns_;
        std::copy_n(volumes.begin() + first, count, block.volumes.begin());
        groupTests_.push_back(&testPipeline(volumeKinds(volumes.subspan(first, count))));
        volumes_->writeObject(block, g * blockBytes_);
    }
}

void GpuCasterCulling::dispatch(rhi::CommandList& commands)
{
    const std::vector<CulledDraw>& draws = scratch_.draws;
    const auto batchCount = static_cast<std::uint32_t>(batches_.batches.size());
    const std::uint32_t chunkPlaces = chunkRuns_ * kCullingRunPlaces;
    for (std::uint32_t g = 0; g < groups_; ++g) {
        const std::uint32_t first = g * groupTiles_, count = std::min(groupTiles_, tileCount_ - first);
        const std::uint64_t slots = std::uint64_t(first) * tileSlots_, groupSlots = std::uint64_t(count) * tileSlots_;
        const rhi::ComputePipeline& test = *groupTests_[g];
        // The tests mark each tile's casters, then one workgroup per tile and chunk of places lays its list out.
        for (const rhi::ComputePipeline* pipeline :
             {&test, static_cast<const rhi::ComputePipeline*>(listsPipeline_.get())}) {
            commands.bindComputePipeline(*pipeline);
            commands.bindUniformBuffer(kTilesBinding, *volumes_, g * blockBytes_, sizeof(CullingTiles));
            commands.bindStorageBuffer(bindingOf(kCasters), *casters_, 0,
                                       scratch_.casters.size() * sizeof(CullingCaster));
            commands.bindStorageBuffer(bindingOf(kTransforms), *transforms_, 0,
                                       scratch_.transforms.size() * sizeof(InstanceTransform));
            commands.bindStorageBuffer(bindingOf(kInstances), *instances_, slots * sizeof(InstanceTransform),
                                       groupSlots * sizeof(InstanceTransform));
            commands.bindStorageBuffer(bindingOf(kIndices), *indices_, slots * sizeof(std::uint32_t),
                                       groupSlots * sizeof(std::uint32_t));
            commands.bindStorageBuffer(bindingOf(kDraws), *draws_, 0, draws.size() * sizeof(CulledDraw));
            commands.bindStorageBuffer(bindingOf(kCounts), *counts_, 0, draws.size() * sizeof(std::uint32_t));
            commands.bindStorageBuffer(bindingOf(kOrder), *order_, 0,
                                       (casterCount_ + batchCount + 1) * sizeof(std::uint32_t));
            commands.bindStorageBuffer(bindingOf(kMarks), *marks_, 0,
                                       std::uint64_t(tileCount_) * markWords(tileSlots_) * sizeof(std::uint32_t));
            const std::uint32_t groupSize = test.workgroupSize()[0];
            if (pipeline == &test)
                commands.dispatch((casterCount_ + groupSize - 1) / groupSize);
            else
                commands.dispatch(count, (casterCount_ + chunkPlaces - 1) / chunkPlaces);
        }
    }
}

std::uint64_t GpuCasterCulling::drawOffset(std::uint32_t tile, std::uint32_t batch) const
{
    return (std::uint64_t(tile) * batches_.batches.size() + batch) * sizeof(CulledDraw);
}

std::uint64_t GpuCasterCulling::countOffset(std::uint32_t tile, std::uint32_t batch) const
{
    return (std::uint64_t(tile) * batches_.batches.size() + batch) * sizeof(std::uint32_t);
}

std::vector<std::vector<std::uint32_t>> GpuCasterCulling::readLists() const
{
    std::vector<std::vector<std::uint32_t>> lists(tileCount_);
    if (casterCount_ == 0 || tileCount_ == 0)
        return lists;
    std::vector<CulledDraw> draws(std::size_t(tileCount_) * batches_.batches.size());
    draws_->read(0, std::as_writable_bytes(std::span(draws)));
    std::vector<std::uint32_t> indices(std::size_t(tileCount_) * tileSlots_);
    indices_->read(0, std::as_writable_bytes(std::span(indices)));
    for (std::uint32_t t = 0; t < tileCount_; ++t) {
        for (std::uint32_t b = 0; b < batches_.batches.size(); ++b) {
            const CulledDraw& draw = draws[t * batches_.batches.size() + b];
            lists[t].insert(lists[t].end(), indices.begin() + draw.firstInstance,
                            indices.begin() + draw.firstInstance + draw.instanceCount);
        }
    }
    return lists;
}

} // namespace penumbra::shadows
