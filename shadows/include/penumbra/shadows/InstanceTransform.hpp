#pragma once

#include "penumbra/rhi/Pipeline.hpp"

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

// Where one drawn instance of a mesh is: the per-instance vertex data of every pass that draws scene meshes
// (shaders/instance.glsl), so that one instanced draw places any number of copies of a mesh. It holds the model
// matrix's first three rows; the last is (0, 0, 0, 1), as every affine transform's. The shaders derive the normal
// matrix from them, so that an instance is 48 bytes to copy, upload and fetch.
struct InstanceTransform {
    std::array<glm::vec4, 3> rows{glm::vec4(1.0f, 0.0f, 0.0f, 0.0f), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f),
                                  glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)};
};
static_assert(sizeof(InstanceTransform) == 48);

// `model`'s first three rows (its last row is dropped: scene transforms are affine).
InstanceTransform instanceTransform(const glm::mat4& model);

// The instance's first attribute location: the rows take three from here. After every mesh attribute (scene
// vertices use locations 0 to 5).
inline constexpr std::uint32_t kInstanceFirstLocation = 6;

// The vertex buffer slot of the instance transforms in every such pass (the mesh's vertices take slot 0).
inline constexpr std::uint32_t kInstanceSlot = 1;

// Appends the per-instance buffer (InstanceTransform, advancing once per instance) at `slot` and its three Float4
// attributes from kInstanceFirstLocation to `layout`.
void addInstanceAttributes(rhi::VertexLayout& layout, std::uint32_t slot);

} // namespace penumbra::shadows
