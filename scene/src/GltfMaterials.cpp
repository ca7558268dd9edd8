#include "GltfMaterials.hpp"

#include "GltfSamplers.hpp"

#include <algorithm>
#include <cstring>

namespace penumbra::scene::gltf {
namespace {

CasterMode casterMode(const Document& document, const tinygltf::Material& material, const std::string& owner)
{
    if (material.alphaMode == "OPAQUE")
        return CasterMode::On;
    if (material.alphaMode == "MASK")
        return CasterMode::Clip;
    if (material.alphaMode == "BLEND")
        return CasterMode::Dither;
    document.fail(fmt::format("{}: alphaMode '{}' is not OPAQUE, MASK or BLEND", owner, material.alphaMode));
}

// tinygltf decodes images with 1 to 4 channels of 8 or 16 bits; the scene keeps RGBA8.
TextureImage toRgba8(const Document& document, const tinygltf::Image& image, const std::string& owner)
{
    if (image.width <= 0 || image.height <= 0 || image.component < 1 || image.component > 4 ||
        (image.bits != 8 && image.bits != 16))
        document.fail(fmt::format("{}: decoded to {}x{} texels of {} channels of {} bits, which is not an RGBA "
                                  "picture of 8 or 16 bits",
                                  owner, image.width, image.height, image.component, image.bits));
    const auto texels = std::size_t(image.width) * std::size_t(image.height);
    const auto channels = std::size_t(image.component);
    const auto bytesPerChannel = std::size_t(image.bits / 8);
    if (image.image.size() != texels * channels * bytesPerChannel)
        document.fail(fmt::format("{}: {} bytes of pixels for {}x{} texels", owner, image.image.size(), image.width,
                                  image.height));
    TextureImage texture{image.name, std::uint32_t(image.width), std::uint32_t(image.height),
                         std::vector<std::uint8_t>(texels * 4, 255)};
    for (std::size_t t = 0; t < texels; ++t) {
        for (std::size_t c = 0; c < 4; ++c) {
            // Grey (and grey-alpha) pictures spread their first channel over RGB.
            const std::size_t source = channels <= 2 ? (c < 3 ? 0 : (channels == 2 ? 1 : 4)) : c;
            if (source >= channels)
                continue;
            const unsigned char* at = image.image.data() + (t * channels + source) * bytesPerChannel;
            std::uint16_t value = *at;
            if (bytesPerChannel == 2) {
                std::memcpy(&value, at, 2);
                value = std::uint16_t((value + 128) / 257);
            }
            texture.rgba[t * 4 + c] = std::uint8_t(value);
        }
    }
    return texture;
}

} // namespace

std::uint32_t MaterialTable::material(int index, const std::string& primitive)
{
    if (const auto found = materials_.find(index); found != materials_.end())
        return found->second;
    Material material{.name = "glTF default", .baseColor = glm::vec4(1.0f), .metallic = 1.0f, .roughness = 1.0f};
    if (index >= 0) {
        const tinygltf::Material& gltf = document_.at(document_.model().materials, index, "material", primitive);
        const std::string owner = describe("material", index, gltf.name);
        const tinygltf::PbrMetallicRoughness& pbr = gltf.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() != 4)
            document_.fail(fmt::format("{}: baseColorFactor has {} values, expected 4", owner,
                                       pbr.baseColorFactor.size()));
        material.name = gltf.name;
        material.baseColor = glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                       float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]));
        material.metallic = float(pbr.metallicFactor);
        material.roughness = float(pbr.roughnessFactor);
        material.caster = casterMode(document_, gltf, owner);
        material.alphaCutoff = float(gltf.alphaCutoff);
        if (pbr.baseColorTexture.index >= 0)
            material.baseColorTexture = texture(pbr.baseColorTexture.index, owner, TextureColorSpace::Srgb);
    }
    const std::uint32_t sceneIndex = scene_.addMaterial(std::move(material));
    materials_.emplace(index, sceneIndex);
    return sceneIndex;
}

std::uint32_t MaterialTable::texture(int textureIndex, const std::string& owner, TextureColorSpace colorSpace)
{
    if (const auto found = textures_.find({textureIndex, colorSpace}); found != textures_.end())
        return found->second;
    const tinygltf::Model& model = document_.model();
    const tinygltf::Texture& texture = document_.at(model.textures, textureIndex, "texture", owner);
    const std::string textureName = describe("texture", textureIndex, texture.name);
    const int imageIndex = texture.source;
    const tinygltf::Image& image = document_.at(model.images, imageIndex, "image", textureName);
    TextureImage decoded = toRgba8(document_, image, describe("image", imageIndex, image.name));
    decoded.colorSpace = colorSpace;
    decoded.sampler = textureSampler(document_, texture.sampler, textureName);
    scene_.textures.push_back(std::move(decoded));
    const auto sceneIndex = static_cast<std::uint32_t>(scene_.textures.size() - 1);
    textures_.emplace(std::pair{textureIndex, colorSpace}, sceneIndex);
    return sceneIndex;
}

} // namespace penumbra::scene::gltf
