#pragma once

#include "penumbra/rhi/Pipeline.hpp"

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

// Where one drawn instance of a mesh is: the per-instance vertex data of every pass that draws scene meshes
// (shaders/instance.glsl), so that one instanced draw places any number of copies of a mesh.
struct InstanceTransform {
    glm::mat4 model{1.0f};
    // The inverse transpose of model's upper 3 x 3, as columns; column 0's w is the sign of det(model) (a mirroring
    // transform reverses the bitangent).
    std::array<glm::vec4, 3> normalColumns{glm::vec4(1.0f, 0.0f, 0.0f, 1.0f), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f),
                                           glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)};
};
static_assert(sizeof(InstanceTransform) == 112);

InstanceTransform instanceTransform(const glm::mat4& model);

// The instance's first attribute location: the model matrix takes four from here, the normal columns the next three.
// After every mesh attribute (scene vertices use locations 0 to 5).
inline constexpr std::uint32_t kInstanceFirstLocation = 6;

// The vertex buffer slot of the instance transforms in every such pass (the mesh's vertices take slot 0).
inline constexpr std::uint32_t kInstanceSlot = 1;

// Appends the per-instance buffer (InstanceTransform, advancing once per instance) at `slot` and its seven Float4
// attributes from kInstanceFirstLocation to `layout`.
void addInstanceAttributes(rhi::VertexLayout& layout, std::uint32_t slot);

} // namespace penumbra::shadows
