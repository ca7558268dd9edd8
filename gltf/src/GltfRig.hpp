#pragma once

#include "GltfDocument.hpp"
#include "GltfNodes.hpp"

#include "penumbra/scene/Scene.hpp"

#include <string>
#include <vector>

namespace penumbra::gltf {

// Fills scene.rig from the file's nodes, skins, morph targets and animations, for the objects `walk` made, marks
// the objects an animation moves dynamic (scene::Mobility), and poses the scene at rest (skins and the default
// morph weights applied). Leaves the rig empty for a file without skins, morph targets or animations. Throws
// GltfError naming the skin, mesh, animation and accessor of data the Khronos glTF Validator rejects (a joint index
// past the skin's joints, a negative weight, key times not increasing, an output of the wrong count or format);
// weights that do not sum to 1 are normalized with a note (all-zero ones bind the vertex to its first joint).
void readRig(const Document& document, const NodeWalk& walk, scene::Scene& scene, std::vector<std::string>& notes);

// The file's animations as scene::Animation, channels on `rigNode[glTF node]`; channels without a target node are
// left out (glTF 2.0 section 3.11: "When node isn't defined, channel should be ignored"), and so are channels of a path
// other than translation, rotation, scale and weights (an extension's), with a note.
std::vector<scene::Animation> readAnimations(const Document& document, const std::vector<std::uint32_t>& rigNode,
                                             std::vector<std::string>& notes);

// Morph targets of a mesh: glTF 2.0 section 3.7.2.2, every primitive has as many.
std::size_t targetCount(const tinygltf::Mesh& mesh);

} // namespace penumbra::gltf
