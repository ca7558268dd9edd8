#pragma once

#include "LitDraws.hpp"

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/scene/Camera.hpp"
#include "penumbra/shadows/CasterChanges.hpp"
#include "penumbra/shadows/GpuCasterCulling.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace penumbra::render {

// The opaque lit objects culled against the camera's view on the GPU (ShadowSettings::culling gpu, with instancing):
// the caster culling pass's machinery (shadows::GpuCasterCulling) given the lit objects as its instances, each lit draw
// group (GpuScene::litDrawGroup) as a batch and the camera's frustum as its one volume. The lit pass and the depth
// prepass then draw one indirect draw per group with exactly the instances in view, in object order, and a frame where
// nothing moved does nothing per object on the CPU: the objects stay in GPU storage, and only those that moved
// (GpuScene::objectChanges) are uploaded again. The groups are drawn in the order of their first object, as litDraws
// orders them, so the pictures are the CPU path's byte for byte.
class GpuViewCulling {
public:
    explicit GpuViewCulling(rhi::Device& device) : culling_(device) {}

    // Brings the objects up to the scene's last GpuScene::refresh, and uploads them and the camera's volume.
    void prepare(const GpuScene& scene, const scene::Camera& camera, float aspect);
    // The opaque objects' draws, one per lit draw group, their blocks pushed into `uniforms`.
    void appendDraws(const GpuScene& scene, rhi::UniformArena& uniforms, std::vector<LitDraw>& draws) const;
    // The objects with blended materials (not shadows-only), ascending: litDraws sorts those in view per frame.
    const std::vector<std::uint32_t>& blended() const { return blended_; }

    // The culling whose dispatches the view culling pass records and whose buffers the draws read.
    shadows::GpuCasterCulling& culling() { return culling_; }
    const shadows::GpuCasterCulling& culling() const { return culling_; }

private:
    // Lists the objects anew.
    void rebuild(const GpuScene& scene);

    static constexpr std::uint32_t kNotListed = 0xffffffffu;
    shadows::GpuCasterCulling culling_;
    std::vector<std::uint32_t> objects_; // the opaque lit objects, ascending: the culling's instances
    std::vector<shadows::ShadowCaster> instances_; // per listed object: its mesh, model and lit draw group
    std::vector<shadows::Bounds> bounds_; // per listed object: its world bounds
    std::vector<std::uint32_t> listedAs_; // per object: its place in objects_, or kNotListed
    std::vector<std::uint32_t> blended_;
    shadows::CasterChanges changes_; // of instances_, for the culling's uploads
    std::optional<std::uint64_t> generation_; // of GpuScene::objectChanges at the last prepare
};

} // namespace penumbra::render
