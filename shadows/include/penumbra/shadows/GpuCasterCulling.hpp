#pragma once

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/CasterChanges.hpp"
#include "penumbra/shadows/CasterVolume.hpp"
#include "penumbra/shadows/InstanceBatches.hpp"
#include "penumbra/shadows/InstanceTransform.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace penumbra::shadows {

// One caster as the culling pass reads it: an element of the storage block CullingCasters.
struct alignas(16) CullingCaster {
    glm::vec4 boundsMin{0.0f}; // the world box, xyz
    glm::vec4 boundsMax{0.0f};
};
inline constexpr std::array kCullingCasterFields{
    PENUMBRA_SHADER_FIELD(CullingCaster, boundsMin),
    PENUMBRA_SHADER_FIELD(CullingCaster, boundsMax),
};
inline constexpr shaders::ShaderStruct kCullingCasterStruct{"CullingCaster", sizeof(CullingCaster),
                                                            kCullingCasterFields};
static_assert(shaders::matchesLayout(kCullingCasterStruct, shaders::BlockLayout::Std430, true));

// InstanceTransform as a storage element: what the pass copies into each tile's instances.
inline constexpr std::array kInstanceTransformFields{
    PENUMBRA_SHADER_FIELD(InstanceTransform, rows),
};
inline constexpr shaders::ShaderStruct kInstanceTransformStruct{"InstanceTransform", sizeof(InstanceTransform),
                                                                kInstanceTransformFields};
static_assert(shaders::matchesLayout(kInstanceTransformStruct, shaders::BlockLayout::Std430, true));

// VkDrawIndexedIndirectCommand (GL's DrawElementsIndirectCommand), one per batch per tile.
struct CulledDraw {
    std::uint32_t indexCount = 0;
    std::uint32_t instanceCount = 0; // set by the pass
    std::uint32_t firstIndex = 0;
    std::int32_t vertexOffset = 0;
    std::uint32_t firstInstance = 0; // set by the pass: the batch's first slot in the tile's range
};
inline constexpr std::array kCulledDrawFields{
    PENUMBRA_SHADER_FIELD(CulledDraw, indexCount),    PENUMBRA_SHADER_FIELD(CulledDraw, instanceCount),
    PENUMBRA_SHADER_FIELD(CulledDraw, firstIndex),    PENUMBRA_SHADER_FIELD(CulledDraw, vertexOffset),
    PENUMBRA_SHADER_FIELD(CulledDraw, firstInstance),
};
inline constexpr shaders::ShaderStruct kCulledDrawStruct{"CulledDraw", sizeof(CulledDraw), kCulledDrawFields};
static_assert(shaders::matchesLayout(kCulledDrawStruct, shaders::BlockLayout::Std430, true));
static_assert(sizeof(CulledDraw) == rhi::kDrawIndexedIndirectCommandBytes);

// The places the lists dispatch ranks at once (caster_culling_lists.comp: 64 lanes of 32-bit words), and the most runs
// of them one of its workgroups lays out: a tile's list is laid out by as many workgroups as it has chunks of
// kCullingChunkRuns runs (at most 32 768 places each), so that 10^6 casters keep a GPU's cores busy.
inline constexpr std::uint32_t kCullingRunPlaces = 64 * 32;
inline constexpr std::uint32_t kCullingChunkRuns = 16;

// The most tiles one dispatch culls: its CullingTiles fill 15 392 bytes of the 16 384 that every device's uniform
// blocks hold at least (Vulkan 1.3's required limits, maxUniformBufferRange; GL 4.5's, MAX_UNIFORM_BLOCK_SIZE).
inline constexpr std::uint32_t kCullingTilesPerDispatch = 64;

// The uniform block CullingTiles: one dispatch's share of the tiles. Every invocation reads the same volumes, which
// a uniform block gives it as uniform values; llvmpipe and lavapipe (Mesa 22.3) read a storage block lane by lane
// (gallivm's emit_load_mem), which cost the 10^4-caster dispatch most of its 25 ms.
struct alignas(16) CullingTiles {
    std::uint32_t casterCount = 0;
    std::uint32_t tileCount = 0; // the dispatch's tiles, firstTile onwards
    std::uint32_t batchCount = 0;
    std::uint32_t firstTile = 0;
    std::uint32_t tileSlots = 0; // instance slots per tile: the caster count, rounded up for the binding offsets
    std::uint32_t markWords = 0; // words of each tile's bits: two per 64 slots, one pair per first dispatch's workgroup
    std::uint32_t chunkRuns = 0; // runs of kCullingRunPlaces places per workgroup of the lists dispatch
    std::array<CasterVolume, kCullingTilesPerDispatch> volumes;
};
static_assert(sizeof(CullingTiles) <= 16384);

// Shadow casters culled per tile on the GPU (shaders/caster_culling.comp): every caster's world box is tested against
// every tile's CasterVolume with casterInVolume's rules and marked in the tile's bits; then one workgroup per tile and
// chunk of kCullingChunkRuns runs of places (shaders/caster_culling_lists.comp) lays the marked casters out in the
// tile's range of the instance lists (their InstanceTransforms, and their indices) in the batches' order, caster order
// within a batch, the same every run, and sets the tile's draw of each batch, an indexed indirect command. Tile t's
// range holds a slot for every caster (tileSlots() of them); the draw of batch b in tile t is command t * batches + b,
// and its count (0 or 1, for drawIndexedIndirectCount) says whether it has instances. The tiles are culled in as few
// dispatches as the device's storage range and CullingTiles allow, each binding the instance ranges of its tiles only,
// so that 10^6 casters fit where all tiles' ranges together would not.
class GpuCasterCulling {
public:
    // `maxTilesPerDispatch`: the most tiles one dispatch culls, fewer where their instances exceed the device's
    // storage range; `chunkRuns`: the runs of places one workgroup lays out, 1 to kCullingChunkRuns (tests give small
    // numbers to see tiles culled over several dispatches and lists laid out in several chunks).
    explicit GpuCasterCulling(rhi::Device& device,
                              std::uint32_t maxTilesPerDispatch = std::numeric_limits<std::uint32_t>::max(),
                              std::uint32_t chunkRuns = kCullingChunkRuns);

    // Uploads the casters, their world boxes (casters[i]'s is bounds[i]) and the tiles' volumes, and makes the
    // buffers the results go to (instances(), draws(), drawCounts() hold from here on, for a frame graph to declare).
    // The casters stay in GPU storage from prepare to prepare: with `changes` (the log of the list the casters come
    // from, GpuScene::casterChanges) only the casters changed since the last prepare are uploaded again, their models
    // and boxes; everything is uploaded without it, where changes->since() says all, or where the count differs. Throws
    // rhi::Error where the counts differ, for casters of a draw group that do not draw alike, and where one tile's
    // instances exceed the device's storage range (Capabilities::maxStorageBufferRange).
    void prepare(std::span<const ShadowCaster> casters, std::span<const Bounds> bounds,
                 std::span<const CasterVolume> volumes, const CasterChanges* changes = nullptr);
    // Records the dispatches of the last prepare() (outside passes).
    void dispatch(rhi::CommandList& commands);
    // prepare(), then dispatch().
    void record(rhi::CommandList& commands, std::span<const ShadowCaster> casters, std::span<const Bounds> bounds,
                std::span<const CasterVolume> volumes, const CasterChanges* changes = nullptr);

    // The casters the last prepare uploaded (for tests): ascending disjoint ranges.
    const std::vector<CasterRange>& uploaded() const { return uploaded_; }

    // The batches of the last record: batches().batches[b] is drawn by command tile * batches + b.
    const InstanceBatches& batches() const { return batches_; }
    const rhi::Buffer& instances() const { return *instances_; }
    const rhi::Buffer& draws() const { return *draws_; }
    const rhi::Buffer& drawCounts() const { return *counts_; }
    // The byte offsets of tile t's draw of batch b in draws() and of its count in drawCounts().
    std::uint64_t drawOffset(std::uint32_t tile, std::uint32_t batch) const;
    std::uint64_t countOffset(std::uint32_t tile, std::uint32_t batch) const;

    // After the submission: each tile's casters as its draws hold them, in the batches' order and caster order within a
    // batch (for tests; reads the GPU's lists back).
    std::vector<std::vector<std::uint32_t>> readLists() const;

private:
    void reserve(std::uint64_t casters, std::uint64_t volumeBytes, std::uint64_t draws);
    // Every caster's box, batch and transform into the scratch storage.
    void fillCasters(std::span<const ShadowCaster> casters, std::span<const Bounds> bounds);
    // The changed casters' boxes and transforms only (their batches stay).
    void fillChanged(std::span<const ShadowCaster> casters, std::span<const Bounds> bounds,
                     std::span<const CasterRange> changed);
    // Every tile's draws, with no instances yet.
    void fillDraws(std::span<const ShadowCaster> casters);
    // The uploaded_ ranges of the casters and transforms.
    void uploadCasters();
    void uploadTiles(std::span<const CasterVolume> volumes);

    rhi::Device& device_;
    // The tests' pipelines, one for each set of volume kinds (VolumeKinds bits) a dispatch's tiles hold, made when
    // first needed: llvmpipe and lavapipe run every branch of a shader for every lane, taken or not, so each leaves out
    // the tests of the kinds its tiles do not hold.
    struct TestPipeline {
        std::unique_ptr<rhi::Shader> shader;
        std::unique_ptr<rhi::ComputePipeline> pipeline;
    };
    const rhi::ComputePipeline& testPipeline(std::uint32_t kinds);
    std::array<TestPipeline, 8> testPipelines_;
    std::vector<const rhi::ComputePipeline*> groupTests_; // each dispatch's tests
    std::unique_ptr<rhi::Shader> listsShader_;
    std::unique_ptr<rhi::ComputePipeline> listsPipeline_;
    std::unique_ptr<rhi::Buffer> volumes_;
    std::unique_ptr<rhi::Buffer> casters_;
    std::unique_ptr<rhi::Buffer> transforms_;
    std::unique_ptr<rhi::Buffer> instances_;
    std::unique_ptr<rhi::Buffer> indices_;
    std::unique_ptr<rhi::Buffer> draws_;
    std::unique_ptr<rhi::Buffer> counts_;
    // batches_.items (the casters in their batches' order), then each batch's first place and the caster count
    std::unique_ptr<rhi::Buffer> order_;
    std::unique_ptr<rhi::Buffer> marks_; // per tile, a bit per place in that order: the caster is in the tile
    InstanceBatches batches_;
    // What record() uploads, kept from frame to frame: fresh vectors of 10^5 elements cost more in page faults than
    // filling them.
    struct Scratch {
        std::vector<std::uint32_t> all;
        std::vector<std::uint32_t> order; // what order_ holds
        std::vector<CullingCaster> casters;
        std::vector<InstanceTransform> transforms;
        std::vector<CulledDraw> draws;
        CullingTiles tiles;
    } scratch_;
    // What the casters and transforms buffers hold: the generation of the changes they were uploaded at and the
    // count; nullopt before the first upload or after a record that uploaded nothing.
    struct Resident {
        std::optional<std::uint64_t> generation;
        std::uint32_t casters = 0;
    };
    std::optional<Resident> resident_;
    std::vector<CasterRange> uploaded_;
    std::uint32_t casterCount_ = 0;
    std::uint32_t tileCount_ = 0;
    std::uint32_t tileSlots_ = 0;
    // The dispatches prepare() set up: groups_ of groupTiles_ tiles (the last fewer), each with a block of
    // blockBytes_ in the volumes buffer; none where there is nothing to cull.
    std::uint32_t groups_ = 0;
    std::uint32_t groupTiles_ = 0;
    std::uint64_t blockBytes_ = 0;
    std::uint32_t maxTilesPerDispatch_;
    std::uint32_t chunkRuns_;
};

} // namespace penumbra::shadows
