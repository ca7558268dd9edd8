#pragma once

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Pipeline.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace penumbra::render {

// Skins and morphs the scene's deformed meshes on the GPU (shaders/skinning.comp): each frame one dispatch per
// scene::Deformer turns its rest vertices, uploaded once, into its pose (scene::Rig::pose, which scene::poseScene
// sets), written into the mesh's vertex buffer in GpuScene. Every pass that draws the mesh (depth prepasses, shadow
// casters of every light kind, lit pass, reference lit pass, debug views) then reads the posed vertices, so a pose is
// computed once per frame, not once per pass, light and cube face (the way Unreal Engine's GPU Skin Cache works).
// The CPU path (scene/Skinning.hpp) stays the reference that the ground truth ray casts.
class GpuSkinning {
public:
    GpuSkinning(rhi::Device& device, const GpuScene& scene);
    ~GpuSkinning();

    // Whether the scene has meshes to deform.
    bool empty() const { return deformers_.empty(); }
    // Writes the scene's current pose and records the dispatches (outside passes).
    void record(rhi::CommandList& commands);
    // The vertex buffers record() writes: the deformed meshes' in GpuScene.
    std::vector<const rhi::Buffer*> posedVertices() const;
    // The bind-pose (rest) vertices of a mesh that is drawn deformed, as a vertex buffer; nullptr for other meshes.
    // For the negative control that leaves skinning out of the shadow casters.
    const rhi::Buffer* restVertices(std::uint32_t mesh) const;

private:
    struct Deformer {
        std::uint32_t mesh = 0;
        std::uint32_t vertexCount = 0;
        std::int32_t skin = -1;
        std::unique_ptr<rhi::Buffer> deform; // DeformHeader and the morph weights, rewritten per frame
        std::unique_ptr<rhi::Buffer> rest;
        std::unique_ptr<rhi::Buffer> influences;
        std::unique_ptr<rhi::Buffer> targets;
    };

    rhi::Device& device_;
    const GpuScene& scene_;
    std::unique_ptr<rhi::ComputePipeline> pipeline_;
    std::vector<Deformer> deformers_;
    std::vector<std::unique_ptr<rhi::Buffer>> joints_; // per skin, rewritten per frame
};

} // namespace penumbra::render
