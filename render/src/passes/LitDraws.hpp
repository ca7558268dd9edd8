#pragma once

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/scene/ViewFrustum.hpp"
#include "penumbra/shadows/GpuCasterCulling.hpp"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace penumbra::render {

class GpuViewCulling;

// One draw of the lit pass and the depth prepass: instanceCount instances of an object's mesh with its material, or
// with `culling` the draw of its view's batch `batch`, whose instances and count the culling pass wrote.
struct LitDraw {
    std::uint32_t object = 0; // the first instance's object, whose mesh and material every instance shares
    std::uint32_t instanceCount = 0;
    rhi::UniformSlice uniforms; // LitObjectUniforms (shaders/lit.glsl, Object)
    rhi::BufferSlice instances; // a shadows::InstanceTransform per instance (with `culling`: its whole list)
    const shadows::GpuCasterCulling* culling = nullptr; // the view's culling, whose draw of `batch` this is; or none
    std::uint32_t batch = 0;
};

// A frame's lit draws, their blocks and instances pushed into the arenas. Opaque and masked objects first, the
// objects of each lit draw group (GpuScene::litDrawGroup) as one draw, the groups in the order of their first opaque
// object in the scene, in view or not (order does not change depth-tested opaque surfaces but where two meet at one
// depth, and a fixed order draws those alike from view to view); then blended ones from the farthest to the nearest
// (their world bounds' centres from the camera), so each blends over what lies behind it (glTF 2.0 section 3.9.4,
// BLEND), consecutive ones of one group as one draw. Shadows-only objects are not drawn, nor objects whose world
// bounds lie outside the view (`frustum`), which could draw no fragment. Without `instanced`, a draw per object. With
// `culled` (prepared for this frame; only with `instanced`) the opaque draws are its indirect ones, which draw the same
// pictures without per-object work on the CPU, and only the blended objects are read.
std::vector<LitDraw> litDraws(const GpuScene& scene, const glm::vec3& camera, const scene::ViewFrustum& frustum,
                              bool instanced, rhi::UniformArena& uniforms, rhi::VertexArena& instances,
                              const GpuViewCulling* culled = nullptr);

// Binds the draw's material maps (kLitMaterialMapBinding, kLitCoverageMapBinding), mesh and instances, and draws it.
void recordLitDraw(rhi::CommandList& commands, const GpuScene& scene, const LitDraw& draw);

// How the lit pass and the depth prepass draw an object: not at all (shadows only), as an opaque surface (also
// alpha-tested: depth-tested, batched by lit draw group) or blended (back to front, not in the prepass).
enum class LitRole { None, Opaque, Blended };
LitRole litRole(const scene::Scene& scene, const scene::Object& object);

// The block of an object's lit draw (the same for every object of its lit draw group).
LitObjectUniforms litObjectUniforms(const scene::Scene& scene, const scene::Object& object);

} // namespace penumbra::render
