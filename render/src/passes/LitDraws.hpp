#pragma once

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/scene/ViewFrustum.hpp"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace penumbra::render {

class LitInstances;

// One draw of the lit pass and the depth prepass: instanceCount instances of an object's mesh with its material.
struct LitDraw {
    std::uint32_t object = 0; // the first instance's object, whose mesh and material every instance shares
    std::uint32_t instanceCount = 0;
    rhi::UniformSlice uniforms; // LitObjectUniforms (shaders/lit.glsl, Object)
    rhi::BufferSlice instances; // a shadows::InstanceTransform per instance
};

// A frame's lit draws, their blocks and instances pushed into the arenas. Opaque and masked objects first, the
// objects of each lit draw group (GpuScene::litDrawGroup) as one draw in the order of its first object (order does
// not change depth-tested opaque surfaces); then blended ones from the farthest to the nearest (their world bounds'
// centres from the camera), so each blends over what lies behind it (glTF 2.0 section 3.9.4, BLEND), consecutive
// ones of one group as one draw. Shadows-only objects are not drawn, nor objects whose world bounds lie outside the
// view (`frustum`), which could draw no fragment. Without `instanced`, a draw per object. With `resident` (updated to
// the scene's last refresh; only with `instanced`) the opaque draws are its own, which draw the same pictures without
// per-object work, and only the blended objects are read.
std::vector<LitDraw> litDraws(const GpuScene& scene, const glm::vec3& camera, const scene::ViewFrustum& frustum,
                              bool instanced, rhi::UniformArena& uniforms, rhi::VertexArena& instances,
                              const LitInstances* resident = nullptr);

// The block of an object's lit draw (the same for every object of its lit draw group).
LitObjectUniforms litObjectUniforms(const scene::Scene& scene, const scene::Object& object);

} // namespace penumbra::render
