#include "GltfMaterials.hpp"

#include "GltfSamplers.hpp"

#include <algorithm>
#include <limits>

namespace penumbra::gltf {
namespace {

scene::CasterMode casterMode(const Document& document, const tinygltf::Material& material, const std::string& owner)
{
    if (material.alphaMode == "OPAQUE")
        return scene::CasterMode::On;
    if (material.alphaMode == "MASK")
        return scene::CasterMode::Clip;
    if (material.alphaMode == "BLEND")
        return scene::CasterMode::Dither;
    document.fail(fmt::format("{}: alphaMode '{}' is not OPAQUE, MASK or BLEND", owner, material.alphaMode));
}

// decodeImage leaves every picture's `pixels` RGBA8, as the scene keeps them.
scene::TextureImage toRgba8(const Document& document, const tinygltf::Image& image, std::vector<unsigned char> pixels,
                            const std::string& owner)
{
    if (image.width <= 0 || image.height <= 0 || image.component != 4 || image.bits != 8)
        document.fail(fmt::format("{}: decoded to {}x{} texels of {} channels of {} bits, which is not an RGBA "
                                  "picture of 8 bits",
                                  owner, image.width, image.height, image.component, image.bits));
    if (pixels.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        document.fail(
            fmt::format("{}: {} bytes of pixels for {}x{} texels", owner, pixels.size(), image.width, image.height));
    return {image.name, std::uint32_t(image.width), std::uint32_t(image.height), std::move(pixels)};
}

double number(const Document& document, const tinygltf::Value& value, const std::string& field)
{
    if (!value.IsNumber() && !value.IsInt())
        document.fail(fmt::format("{} is not a number", field));
    return value.GetNumberAsDouble();
}

// A value of a glTF field that must lie in [low, high].
float inRange(const Document& document, double value, double low, double high, const std::string& field)
{
    if (!(value >= low && value <= high))
        document.fail(fmt::format("{} {} is outside [{}, {}]", field, value, low, high));
    return float(value);
}

// A texture coordinate set the passes read (TEXCOORD_0 or TEXCOORD_1); the schema check has bounded it by the sets
// the primitive has.
std::uint32_t supportedSet(const Document& document, double set, const std::string& field)
{
    if (set > scene::kTexCoordSets - 1)
        document.fail(fmt::format("{} {}: texture coordinate sets past TEXCOORD_{} are not supported", field, set,
                                  scene::kTexCoordSets - 1));
    return std::uint32_t(set);
}

glm::vec2 vec2Field(const Document& document, const tinygltf::Value& object, const char* key, glm::vec2 fallback,
                    const std::string& owner)
{
    if (!object.Has(key))
        return fallback;
    const tinygltf::Value& value = object.Get(key);
    const std::string field = fmt::format("{}.{}", owner, key);
    if (!value.IsArray() || value.ArrayLen() != 2)
        document.fail(fmt::format("{} is not an array of 2 numbers", field));
    return {float(number(document, value.Get(0), field)), float(number(document, value.Get(1), field))};
}

// KHR_texture_transform on a textureInfo: offset, rotation, scale, and a texCoord that overrides the
// textureInfo's.
void readTextureTransform(const Document& document, const tinygltf::ExtensionMap& extensions,
                          scene::MaterialTexture& texture, const std::string& owner)
{
    const auto found = extensions.find("KHR_texture_transform");
    if (found == extensions.end())
        return;
    const tinygltf::Value& value = found->second;
    const std::string field = owner + ".extensions.KHR_texture_transform";
    texture.transform.offset = vec2Field(document, value, "offset", glm::vec2(0.0f), field);
    texture.transform.scale = vec2Field(document, value, "scale", glm::vec2(1.0f), field);
    if (value.Has("rotation"))
        texture.transform.rotation = float(number(document, value.Get("rotation"), field + ".rotation"));
    if (value.Has("texCoord"))
        texture.texCoord =
            supportedSet(document, number(document, value.Get("texCoord"), field + ".texCoord"), field + ".texCoord");
}

const tinygltf::Value* extension(const tinygltf::Material& material, const std::string& name)
{
    const auto found = material.extensions.find(name);
    return found == material.extensions.end() ? nullptr : &found->second;
}

} // namespace

std::uint32_t MaterialTable::material(int index, const std::string& primitive)
{
    if (const auto found = materials_.find(index); found != materials_.end())
        return found->second;
    scene::Material material{.name = "glTF default", .baseColor = glm::vec4(1.0f), .metallic = 1.0f, .roughness = 1.0f};
    if (index >= 0) {
        const tinygltf::Material& gltf = document_.at(document_.model().materials, index, "material", primitive);
        const std::string owner = describe("material", index, gltf.name);
        const tinygltf::PbrMetallicRoughness& pbr = gltf.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() != 4)
            document_.fail(
                fmt::format("{}: baseColorFactor has {} values, expected 4", owner, pbr.baseColorFactor.size()));
        const auto unit = [&](double value, const std::string& field) {
            return inRange(document_, value, 0.0, 1.0, fmt::format("{}: {}", owner, field));
        };
        material.name = gltf.name;
        for (int c = 0; c < 4; ++c)
            material.baseColor[c] = unit(pbr.baseColorFactor[std::size_t(c)], "pbrMetallicRoughness.baseColorFactor");
        material.metallic = unit(pbr.metallicFactor, "pbrMetallicRoughness.metallicFactor");
        material.roughness = unit(pbr.roughnessFactor, "pbrMetallicRoughness.roughnessFactor");
        material.caster = casterMode(document_, gltf, owner);
        material.blend = gltf.alphaMode == "BLEND";
        material.alphaCutoff = inRange(document_, gltf.alphaCutoff, 0.0, 1.0, owner + ": alphaCutoff");
        material.doubleSided = gltf.doubleSided;
        material.unlit = extension(gltf, "KHR_materials_unlit") != nullptr;
        if (gltf.emissiveFactor.size() != 3)
            document_.fail(
                fmt::format("{}: emissiveFactor has {} values, expected 3", owner, gltf.emissiveFactor.size()));
        float emissiveStrength = 1.0f;
        if (const tinygltf::Value* strength = extension(gltf, "KHR_materials_emissive_strength");
            strength && strength->Has("emissiveStrength")) {
            const std::string field = owner + ": extensions.KHR_materials_emissive_strength.emissiveStrength";
            emissiveStrength = inRange(document_, number(document_, strength->Get("emissiveStrength"), field), 0.0,
                                       std::numeric_limits<double>::infinity(), field);
        }
        for (int c = 0; c < 3; ++c)
            material.emissive[c] = unit(gltf.emissiveFactor[std::size_t(c)], "emissiveFactor") * emissiveStrength;
        material.normalScale = float(gltf.normalTexture.scale);
        material.occlusionStrength = unit(gltf.occlusionTexture.strength, "occlusionTexture.strength");

        // Base colour and emissive textures hold sRGB-encoded colour, the others linear data (glTF 2.0, section
        // 3.9); one glTF texture read both ways becomes two images.
        const auto read = [&](scene::TextureSlot slot, int textureIndex, int texCoord,
                              const tinygltf::ExtensionMap& extensions, const char* field) {
            if (textureIndex < 0)
                return;
            const std::string where = fmt::format("{}: {}", owner, field);
            // glTF 2.0, section 5.29: a texture without source leaves its image to an extension.
            if (document_.at(document_.model().textures, textureIndex, "texture", where).source < 0) {
                notes_.push_back(fmt::format("{}: texture {} has no source image: left out", where, textureIndex));
                return;
            }
            if (const std::filesystem::path* tried = missingImage(textureIndex, where)) {
                standIn(slot, material, where, *tried);
                return;
            }
            const scene::TextureColorSpace colorSpace =
                slot == scene::TextureSlot::BaseColor || slot == scene::TextureSlot::Emissive
                    ? scene::TextureColorSpace::Srgb
                    : scene::TextureColorSpace::Linear;
            scene::MaterialTexture texture{.image = this->texture(textureIndex, where, colorSpace),
                                           .texCoord = supportedSet(document_, texCoord, where + ".texCoord")};
            readTextureTransform(document_, extensions, texture, where);
            material.texture(slot) = texture;
        };
        read(scene::TextureSlot::BaseColor, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
             pbr.baseColorTexture.extensions, "pbrMetallicRoughness.baseColorTexture");
        read(scene::TextureSlot::MetallicRoughness, pbr.metallicRoughnessTexture.index,
             pbr.metallicRoughnessTexture.texCoord, pbr.metallicRoughnessTexture.extensions,
             "pbrMetallicRoughness.metallicRoughnessTexture");
        read(scene::TextureSlot::Normal, gltf.normalTexture.index, gltf.normalTexture.texCoord,
             gltf.normalTexture.extensions, "normalTexture");
        read(scene::TextureSlot::Occlusion, gltf.occlusionTexture.index, gltf.occlusionTexture.texCoord,
             gltf.occlusionTexture.extensions, "occlusionTexture");
        read(scene::TextureSlot::Emissive, gltf.emissiveTexture.index, gltf.emissiveTexture.texCoord,
             gltf.emissiveTexture.extensions, "emissiveTexture");
    }
    const std::uint32_t sceneIndex = scene_.addMaterial(std::move(material));
    materials_.emplace(index, sceneIndex);
    return sceneIndex;
}

const std::filesystem::path* MaterialTable::missingImage(int textureIndex, const std::string& owner) const
{
    const tinygltf::Model& model = document_.model();
    const tinygltf::Texture& texture = document_.at(model.textures, textureIndex, "texture", owner);
    const std::filesystem::path* tried = document_.missingImage(texture.source);
    if (tried && document_.missingTextures() == MissingTextures::Fail) {
        const tinygltf::Image& image = model.images[std::size_t(texture.source)];
        throw GltfMissingImageError(fmt::format("{}: {}: {} '{}' cannot be read (tried {})", document_.path(), owner,
                                                describe("image", texture.source, image.name), image.uri,
                                                tried->string()));
    }
    return tried;
}

void MaterialTable::standIn(scene::TextureSlot slot, scene::Material& material, const std::string& owner,
                            const std::filesystem::path& tried)
{
    // Without the texture the material's factors apply alone (glTF 2.0, section 3.9: a texture multiplies its
    // factor): a flat colour, flat normal, no occlusion. An emissive texture masks where the factor glows; without
    // it nothing glows.
    if (slot == scene::TextureSlot::Emissive)
        material.emissive = glm::vec3(0.0f);
    notes_.push_back(fmt::format("{}: image {} cannot be read: drawn with a flat stand-in", owner, tried.string()));
}

std::uint32_t MaterialTable::texture(int textureIndex, const std::string& owner, scene::TextureColorSpace colorSpace)
{
    if (const auto found = textures_.find({textureIndex, colorSpace}); found != textures_.end())
        return found->second;
    const tinygltf::Model& model = document_.model();
    const tinygltf::Texture& texture = document_.at(model.textures, textureIndex, "texture", owner);
    const std::string textureName = describe("texture", textureIndex, texture.name);
    const int imageIndex = texture.source;
    const tinygltf::Image& image = document_.at(model.images, imageIndex, "image", textureName);
    // The image's pixels go to its first texture; a second use (another sampler or colour space) copies them.
    const auto taken = imageTextures_.find(imageIndex);
    scene::TextureImage decoded =
        toRgba8(document_, image,
                taken == imageTextures_.end() ? document_.takePixels(imageIndex) : scene_.textures[taken->second].rgba,
                describe("image", imageIndex, image.name));
    decoded.colorSpace = colorSpace;
    decoded.sampler = textureSampler(document_, texture.sampler, textureName);
    scene_.textures.push_back(std::move(decoded));
    const auto sceneIndex = static_cast<std::uint32_t>(scene_.textures.size() - 1);
    textures_.emplace(std::pair{textureIndex, colorSpace}, sceneIndex);
    imageTextures_.try_emplace(imageIndex, sceneIndex);
    return sceneIndex;
}

} // namespace penumbra::gltf
