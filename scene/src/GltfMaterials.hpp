#pragma once

#include "GltfDocument.hpp"

#include "penumbra/scene/Scene.hpp"

#include <map>

namespace penumbra::scene::gltf {

// Converts glTF materials into Scene::materials on first use, and the images their base colour
// textures show into Scene::textures (RGBA8), each once however many materials share it.
class MaterialTable {
public:
    MaterialTable(const Document& document, Scene& scene) : document_(document), scene_(scene) {}

    // The scene material for glTF material `index`, which `owner` (a primitive) refers to; -1 is
    // glTF's default material (white, metallic 1, roughness 1, opaque).
    std::uint32_t material(int index, const std::string& owner);

private:
    std::uint32_t texture(int textureIndex, const std::string& owner);

    const Document& document_;
    Scene& scene_;
    std::map<int, std::uint32_t> materials_;
    std::map<int, std::uint32_t> textures_; // by glTF image
};

} // namespace penumbra::scene::gltf
