#pragma once

#include "GltfDocument.hpp"

#include "penumbra/scene/Scene.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>
#include <utility>

namespace penumbra::gltf {

// Converts glTF materials into Scene::materials on first use, and the textures they use into
// Scene::textures (RGBA8 with the texture's sampler), each once per colour space however many materials share it.
class MaterialTable {
public:
    MaterialTable(const Document& document, scene::Scene& scene, std::vector<std::string>& notes)
        : document_(document), scene_(scene), notes_(notes)
    {
    }

    // The scene material for glTF material `index`, which `owner` (a primitive) refers to; -1 is
    // glTF's default material (white, metallic 1, roughness 1, opaque).
    std::uint32_t material(int index, const std::string& owner);

private:
    // The path tried for the image of glTF texture `textureIndex` when it cannot be read, or nullptr; throws
    // GltfMissingImageError when the document does not stand in for missing images.
    const std::filesystem::path* missingImage(int textureIndex, const std::string& owner) const;
    // A material's texture in `slot` whose image at `tried` cannot be read: left out, with a note.
    void standIn(scene::TextureSlot slot, scene::Material& material, const std::string& owner,
                 const std::filesystem::path& tried);
    std::uint32_t texture(int textureIndex, const std::string& owner, scene::TextureColorSpace colorSpace);

    const Document& document_;
    scene::Scene& scene_;
    std::vector<std::string>& notes_;
    std::map<int, std::uint32_t> materials_;
    std::map<std::pair<int, scene::TextureColorSpace>, std::uint32_t> textures_; // by glTF texture
    std::map<int, std::uint32_t> imageTextures_; // by glTF image, the scene texture its pixels went to
};

} // namespace penumbra::gltf
