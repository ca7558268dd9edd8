#include "GltfUnsupported.hpp"

#include <algorithm>
#include <array>
#include <string_view>

namespace penumbra::gltf {
namespace {

constexpr std::array<std::string_view, 5> kSupportedExtensions{"EXT_mesh_gpu_instancing", "KHR_lights_punctual",
                                                               "KHR_materials_emissive_strength", "KHR_materials_unlit",
                                                               "KHR_texture_transform"};

bool supported(const std::string& extension)
{
    return std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), extension) != kSupportedExtensions.end();
}

} // namespace

void checkSupport(const Document& document, std::vector<std::string>& notes)
{
    const tinygltf::Model& model = document.model();
    for (const std::string& extension : model.extensionsRequired)
        if (!supported(extension))
            document.fail(fmt::format("requires extension {}, which is not supported", extension));
    for (const std::string& extension : model.extensionsUsed)
        if (!supported(extension))
            notes.push_back(fmt::format("extension {} is not supported: ignored", extension));
    if (!model.skins.empty())
        notes.push_back(fmt::format("skins are not supported: {} skin(s) ignored, meshes drawn in their bind pose",
                                    model.skins.size()));
    const auto morphed = std::count_if(model.meshes.begin(), model.meshes.end(), [](const tinygltf::Mesh& mesh) {
        return std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                           [](const tinygltf::Primitive& p) { return !p.targets.empty(); });
    });
    if (morphed > 0)
        notes.push_back(fmt::format("morph targets are not supported: {} mesh(es) drawn without them", morphed));
    if (!model.animations.empty())
        notes.push_back(fmt::format("animations are not supported: {} animation(s) ignored", model.animations.size()));
}

} // namespace penumbra::gltf
