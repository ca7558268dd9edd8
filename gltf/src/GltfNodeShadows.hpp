#pragma once

#include "GltfDocument.hpp"

#include "penumbra/scene/Scene.hpp"

namespace penumbra::gltf {

// An object's shadow choices as a node and its ancestors set them.
struct NodeShadows {
    scene::ShadowCasting cast = scene::ShadowCasting::On;
    bool receive = true;
    scene::Mobility mobility = scene::Mobility::Static;
};

// The node's `extras.penumbra` {"castShadows": "on" | "off" | "twoSided" | "shadowsOnly",
// "receiveShadows": true | false, "mobility": "static" | "dynamic"}, each field defaulting to `inherited` (its
// parent's). glTF leaves extras to applications (glTF 2.0 section 3.12); a namespaced object keeps ours apart from what
// other tools (Blender's custom properties) write there. Throws GltfError naming the JSON pointer of
// a field of the wrong type or value.
NodeShadows readNodeShadows(const Document& document, const tinygltf::Node& node, int index,
                            const NodeShadows& inherited);

} // namespace penumbra::gltf
