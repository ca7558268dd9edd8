#pragma once

#include "penumbra/scene/Geometry.hpp"
#include "penumbra/scene/Rig.hpp"

#include <glm/mat4x4.hpp>

#include <span>
#include <vector>

namespace penumbra::scene {

// Morph targets and linear blend skinning on the CPU, as glTF 2.0 sections 3.7.2.2 (morph targets) and 3.7.3
// (skins) define them: the reference the renderer's pose and the ground truth's ray caster share, and that a GPU
// skinning pass is to match.

// glTF 2.0 section 3.7.3.1: joint matrix j = world(skin.joints[j]) * skin.inverseBind[j]; `world` is every rig
// node's world transform.
std::vector<glm::mat4> jointMatrices(const Skin& skin, std::span<const glm::mat4> world);

// The vertex plus each target's offsets times its weight (section 3.7.2.2: position, normal and tangent xyz; the
// tangent's w stays). `vertex` indexes the targets' arrays; missing weights count as 0.
Vertex morphVertex(const Vertex& rest, std::span<const MorphTarget> targets, std::span<const float> weights,
                   std::size_t vertex);

// Section 3.7.3.3: sum over the vertex's influences of weight * jointMatrices[joint].
glm::mat4 skinMatrix(std::span<const glm::uvec4> joints, std::span<const glm::vec4> weights,
                     std::span<const glm::mat4> jointMatrices);

// The vertex moved by a skin matrix: the position by it, the normal by its inverse transpose (right for non-uniform
// scale), the tangent's xyz by it, each direction normalized again.
Vertex skinVertex(const Vertex& vertex, const glm::mat4& skin);

// The deformer's vertices at a pose: morphed by `weights`, then skinned by `jointMatrices` when it has a skin (in
// world space: glTF ignores a skinned mesh node's transform), with flat normals recomputed per triangle when the
// file gave none.
std::vector<Vertex> deformVertices(const Deformer& deformer, std::span<const float> weights,
                                   std::span<const glm::mat4> jointMatrices);

} // namespace penumbra::scene
