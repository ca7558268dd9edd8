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
}

} // namespace penumbra::gltf
