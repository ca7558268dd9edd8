#include "LitInstances.hpp"

#include "penumbra/render/LitUniforms.hpp"

#include <algorithm>
#include <map>

namespace penumbra::render {
namespace {

static_assert(LitInstances::kChunk % LitInstances::kPart == 0);

// Parts [first, end) of one group, in view.
struct LitChunkRun {
    std::uint32_t first = 0;
    std::uint32_t end = 0;
};

// Leaves at most `most` runs: the gaps of at most the (runs - most)-th shortest length are drawn through.
void bridgeShortestGaps(std::vector<LitChunkRun>& runs, std::size_t most)
{
    if (runs.size() <= most)
        return;
    std::vector<std::uint32_t> gaps;
    for (std::size_t r = 1; r < runs.size(); ++r)
        gaps.push_back(runs[r].first - runs[r - 1].end);
    const auto nth = gaps.begin() + std::ptrdiff_t(runs.size() - most - 1);
    std::nth_element(gaps.begin(), nth, gaps.end());
    const std::uint32_t bridged = *nth;
    std::vector<LitChunkRun> merged{runs.front()};
    for (std::size_t r = 1; r < runs.size(); ++r) {
        if (runs[r].first - merged.back().end <= bridged)
            merged.back().end = runs[r].end;
        else
            merged.push_back(runs[r]);
    }
    runs = std::move(merged);
}

} // namespace

void LitInstances::rebuild(const GpuScene& gpuScene)
{
    const scene::Scene& scene = gpuScene.scene();
    // Each group's objects ascending, the groups in the order of their first object.
    std::map<std::uint32_t, std::size_t> groupIndex;
    std::vector<std::vector<std::uint32_t>> members;
    blended_.clear();
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const scene::Object& object = scene.objects[i];
        if (object.castShadows == scene::ShadowCasting::ShadowsOnly)
            continue;
        if (scene.materialOf(object).blend) {
            blended_.push_back(i);
            continue;
        }
        const auto [at, added] = groupIndex.try_emplace(gpuScene.litDrawGroup(i), members.size());
        if (added)
            members.emplace_back();
        members[at->second].push_back(i);
    }
    groups_.clear();
    objects_.clear();
    slotOf_.assign(scene.objects.size(), kNoSlot);
    for (const std::vector<std::uint32_t>& group : members) {
        const auto first = static_cast<std::uint32_t>(objects_.size());
        groups_.push_back({first, static_cast<std::uint32_t>(group.size())});
        for (const std::uint32_t object : group) {
            slotOf_[object] = static_cast<std::uint32_t>(objects_.size());
            objects_.push_back(object);
        }
        // Padding to the next chunk, so that no chunk holds two groups.
        objects_.resize((objects_.size() + kChunk - 1) / kChunk * kChunk, kNoSlot);
    }
    chunkBounds_.assign(objects_.size() / kChunk, scene::Bounds{});
    partBounds_.assign(objects_.size() / kPart, scene::Bounds{});
    const std::uint64_t bytes = std::max<std::uint64_t>(objects_.size(), 1) * sizeof(shadows::InstanceTransform);
    if (!buffer_ || buffer_->desc().size < bytes)
        buffer_ = device_.createBuffer(
            {.size = bytes, .usage = rhi::BufferUsage::Vertex, .debugName = "lit instances (resident)"});
    write(scene, 0, static_cast<std::uint32_t>(objects_.size()));
}

void LitInstances::write(const scene::Scene& scene, std::uint32_t first, std::uint32_t end)
{
    scratch_.clear();
    for (std::uint32_t slot = first; slot < end; ++slot) {
        const std::uint32_t object = objects_[slot];
        scratch_.push_back(
            shadows::instanceTransform(object == kNoSlot ? glm::mat4(1.0f) : scene.objects[object].transform));
    }
    if (!scratch_.empty())
        buffer_->write(first * sizeof(shadows::InstanceTransform), std::as_bytes(std::span(scratch_)));
    constexpr std::uint32_t kParts = kChunk / kPart;
    for (std::uint32_t chunk = first / kChunk; chunk < (end + kChunk - 1) / kChunk; ++chunk) {
        scene::Bounds box;
        for (std::uint32_t part = chunk * kParts; part < (chunk + 1) * kParts; ++part) {
            scene::Bounds partBox;
            for (std::uint32_t slot = part * kPart; slot < (part + 1) * kPart; ++slot)
                if (objects_[slot] != kNoSlot)
                    partBox.extend(scene.objects[objects_[slot]].worldBounds);
            partBounds_[part] = partBox;
            box.extend(partBox);
        }
        chunkBounds_[chunk] = box;
    }
}

void LitInstances::update(const GpuScene& gpuScene)
{
    const shadows::CasterChanges& changes = gpuScene.objectChanges();
    const std::optional<std::vector<shadows::CasterRange>> changed = changes.since(generation_);
    generation_ = changes.generation();
    if (!changed) {
        rebuild(gpuScene);
        return;
    }
    // The moved objects' slots, as runs of consecutive slots written at once.
    std::vector<std::uint32_t> slots;
    for (const shadows::CasterRange& range : *changed)
        for (std::uint32_t object = range.first; object < range.first + range.count; ++object)
            if (slotOf_[object] != kNoSlot)
                slots.push_back(slotOf_[object]);
    std::sort(slots.begin(), slots.end());
    for (std::size_t begin = 0; begin < slots.size();) {
        std::size_t end = begin + 1;
        while (end < slots.size() && slots[end] == slots[end - 1] + 1)
            ++end;
        write(gpuScene.scene(), slots[begin], slots[end - 1] + 1);
        begin = end;
    }
}

void LitInstances::appendDraws(const GpuScene& gpuScene, const scene::ViewFrustum& frustum, rhi::UniformArena& uniforms,
                               std::vector<LitDraw>& draws) const
{
    const scene::Scene& scene = gpuScene.scene();
    struct Shown {
        std::uint32_t firstObject = 0; // its first object in view, by litDraws' per-object test
        std::size_t group = 0;
        std::vector<LitChunkRun> runs;
    };
    std::vector<Shown> shown;
    for (std::size_t g = 0; g < groups_.size(); ++g) {
        const Group& group = groups_[g];
        std::vector<LitChunkRun> runs;
        const std::uint32_t end = group.first + group.count;
        const std::uint32_t endChunk = (end + kChunk - 1) / kChunk;
        for (std::uint32_t chunk = group.first / kChunk; chunk < endChunk; ++chunk) {
            if (!frustum.mayShow(chunkBounds_[chunk]))
                continue;
            // The chunk's parts that hold objects of the group, those in view.
            const std::uint32_t endPart = std::min((chunk + 1) * kChunk, end + kPart - 1) / kPart;
            for (std::uint32_t part = chunk * kChunk / kPart; part < endPart; ++part) {
                if (!frustum.mayShow(partBounds_[part]))
                    continue;
                if (!runs.empty() && runs.back().end == part)
                    runs.back().end = part + 1;
                else
                    runs.push_back({part, part + 1});
            }
        }
        // The group's place among the draws: its first object that litDraws keeps; none, and it draws nothing.
        std::optional<std::uint32_t> firstObject;
        for (std::size_t r = 0; r < runs.size() && !firstObject; ++r)
            for (std::uint32_t slot = runs[r].first * kPart; slot < runs[r].end * kPart && !firstObject; ++slot)
                if (objects_[slot] != kNoSlot && frustum.mayShow(scene.objects[objects_[slot]].worldBounds))
                    firstObject = objects_[slot];
        if (!firstObject)
            continue;
        bridgeShortestGaps(runs, kMaxRuns);
        shown.push_back({*firstObject, g, std::move(runs)});
    }
    std::sort(shown.begin(), shown.end(), [](const Shown& a, const Shown& b) { return a.firstObject < b.firstObject; });
    for (const Shown& s : shown) {
        const Group& group = groups_[s.group];
        const std::uint32_t object = objects_[group.first];
        const rhi::UniformSlice block = uniforms.push(litObjectUniforms(scene, scene.objects[object]));
        for (const LitChunkRun& run : s.runs) {
            const std::uint32_t first = run.first * kPart;
            const std::uint32_t end = std::min(run.end * kPart, group.first + group.count);
            constexpr std::uint64_t kBytes = sizeof(shadows::InstanceTransform);
            draws.push_back({object, end - first, block, {buffer_.get(), first * kBytes, (end - first) * kBytes}});
        }
    }
}

} // namespace penumbra::render
