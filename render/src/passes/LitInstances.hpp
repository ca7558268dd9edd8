#pragma once

#include "LitDraws.hpp"

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/scene/ViewFrustum.hpp"
#include "penumbra/shadows/InstanceTransform.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace penumbra::render {

// The opaque lit objects' instance transforms kept in one vertex buffer from frame to frame, so that a frame where
// nothing moved does nothing per object for the lit pass and the depth prepass (ShadowSettings::culling gpu). Each lit
// draw group's objects lie together in ascending order, in chunks of kChunk whose world boxes are kept beside them;
// a frame's view culling tests the chunks, not the objects, and draws each run of chunks that the view may show. That
// draws a superset of litDraws' objects in the same order (groups in the order of their first object in view, objects
// ascending), and the objects it adds lie wholly outside a plane of the view, which no fragment passes: the pictures
// are those of litDraws, byte for byte. Only objects that moved (GpuScene::objectChanges) are written again.
class LitInstances {
public:
    // Instances per chunk: 10^6 objects are 15 625 box tests a frame.
    static constexpr std::uint32_t kChunk = 64;
    // Instances per part of a chunk: the parts of the chunks in view are tested too, and drawn where in view, which
    // costs in proportion to the chunks in view only. At 10^4 cubes, 5 441 instances drawn instead of 6 592 (the
    // per-object list: 4 326), each one vertex work through the depth prepass and the lit pass.
    static constexpr std::uint32_t kPart = 16;
    // At most this many draws per group: the shortest gaps between runs are drawn where there would be more, so that
    // the recording does not grow with the instances either.
    static constexpr std::size_t kMaxRuns = 64;

    explicit LitInstances(rhi::Device& device) : device_(device) {}

    // Brings the buffer and the chunks' boxes up to the scene's last GpuScene::refresh.
    void update(const GpuScene& scene);
    // The opaque objects' draws (as litDraws makes them with instancing), their blocks pushed into `uniforms`.
    void appendDraws(const GpuScene& scene, const scene::ViewFrustum& frustum, rhi::UniformArena& uniforms,
                     std::vector<LitDraw>& draws) const;
    // The objects with blended materials (not shadows-only), ascending: litDraws sorts those in view per frame.
    const std::vector<std::uint32_t>& blended() const { return blended_; }

private:
    // Builds everything anew.
    void rebuild(const GpuScene& scene);
    // Slots [first, end): their transforms into the buffer, their chunks' and parts' boxes anew.
    void write(const scene::Scene& scene, std::uint32_t first, std::uint32_t end);

    struct Group {
        std::uint32_t first = 0; // its first slot (a multiple of kChunk)
        std::uint32_t count = 0;
    };
    static constexpr std::uint32_t kNoSlot = 0xffffffffu;
    rhi::Device& device_;
    std::vector<Group> groups_; // in the order of their first object
    std::vector<std::uint32_t> objects_; // per slot: its object, kNoSlot for the padding after a group
    std::vector<std::uint32_t> slotOf_; // per object: its slot, or kNoSlot
    std::vector<scene::Bounds> chunkBounds_; // per chunk of kChunk slots
    std::vector<scene::Bounds> partBounds_; // per part of kPart slots
    std::vector<std::uint32_t> blended_;
    std::unique_ptr<rhi::Buffer> buffer_;
    std::optional<std::uint64_t> generation_; // of GpuScene::objectChanges at the last update
    std::vector<shadows::InstanceTransform> scratch_;
};

} // namespace penumbra::render
