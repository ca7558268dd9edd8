#include "GltfSchema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <numbers>

namespace penumbra::gltf {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

// A textureInfo (glTF 2.0, section 5.22) and its KHR_texture_transform; returns the texture
// coordinate set it reads.
std::int64_t checkTextureInfo(const Fields& info)
{
    info.require("index");
    info.index("index", "textures");
    std::int64_t texCoord = info.integer("texCoord", 0, kMaxInteger).value_or(0);
    if (const auto transform = info.extension("KHR_texture_transform")) {
        transform->numbers("offset", 2);
        transform->numbers("scale", 2);
        transform->number("rotation", -kInfinity, kInfinity);
        texCoord = transform->integer("texCoord", 0, kMaxInteger).value_or(texCoord);
    }
    return texCoord;
}

// The highest texture coordinate set the material reads, or -1.
std::int64_t checkMaterial(const Fields& material)
{
    std::int64_t texCoord = -1;
    const auto texture = [&](const Fields& owner, const char* key) {
        if (const auto info = owner.object(key))
            texCoord = std::max(texCoord, checkTextureInfo(*info));
    };
    if (const auto pbr = material.object("pbrMetallicRoughness")) {
        pbr->numbers("baseColorFactor", 4, 0.0, 1.0);
        pbr->number("metallicFactor", 0.0, 1.0);
        pbr->number("roughnessFactor", 0.0, 1.0);
        texture(*pbr, "baseColorTexture");
        texture(*pbr, "metallicRoughnessTexture");
    }
    texture(material, "normalTexture");
    texture(material, "occlusionTexture");
    texture(material, "emissiveTexture");
    if (const auto normal = material.object("normalTexture"))
        normal->number("scale", -kInfinity, kInfinity);
    if (const auto occlusion = material.object("occlusionTexture"))
        occlusion->number("strength", 0.0, 1.0);
    material.numbers("emissiveFactor", 3, 0.0, 1.0);
    material.oneOf("alphaMode", {"OPAQUE", "MASK", "BLEND"});
    material.number("alphaCutoff", 0.0, kInfinity);
    material.boolean("doubleSided");
    if (const auto strength = material.extension("KHR_materials_emissive_strength"))
        strength->number("emissiveStrength", 0.0, kInfinity);
    return texCoord;
}

} // namespace

void checkMaterials(const JsonFile& file)
{
    std::vector<std::int64_t> texCoords;
    for (const Fields& material : topLevel(file, "materials"))
        texCoords.push_back(checkMaterial(material));
    // A material's textures read texture coordinate sets every primitive using it must have.
    for (const Fields& mesh : topLevel(file, "meshes")) {
        for (const Fields& primitive : mesh.objects("primitives")) {
            const auto material = primitive.index("material", "materials");
            if (!material || !primitive.has("attributes") || !primitive.json()["attributes"].is_object())
                continue;
            for (std::int64_t set = 0; set <= texCoords[std::size_t(*material)]; ++set)
                if (!primitive.json()["attributes"].contains(fmt::format("TEXCOORD_{}", set)))
                    primitive.fail("material", fmt::format("material {} reads TEXCOORD_{}, which the primitive lacks",
                                                           *material, set));
        }
    }
}

void checkTexturesAndImages(const JsonFile& file)
{
    for (const Fields& sampler : topLevel(file, "samplers")) {
        sampler.oneOf("magFilter", {9728, 9729});
        sampler.oneOf("minFilter", {9728, 9729, 9984, 9985, 9986, 9987});
        sampler.oneOf("wrapS", {33071, 33648, 10497});
        sampler.oneOf("wrapT", {33071, 33648, 10497});
    }
    for (const Fields& texture : topLevel(file, "textures")) {
        texture.index("sampler", "samplers");
        texture.index("source", "images");
    }
    for (const Fields& image : topLevel(file, "images")) {
        const bool uri = image.string("uri").has_value();
        const bool view = image.index("bufferView", "bufferViews").has_value();
        if (uri == view)
            file.fail(image.pointer(), "an image has either a uri or a bufferView");
        image.oneOf("mimeType", {"image/jpeg", "image/png"});
        if (view && !image.has("mimeType"))
            image.fail("bufferView", "an image in a buffer view needs a mimeType");
    }
}

void checkCamerasAndLights(const JsonFile& file)
{
    for (const Fields& camera : topLevel(file, "cameras")) {
        camera.require("type");
        const std::string type = *camera.oneOf("type", {"perspective", "orthographic"});
        if (camera.has("perspective") && camera.has("orthographic"))
            file.fail(camera.pointer(), "a camera is either perspective or orthographic, not both");
        camera.require(type);
        const Fields projection = *camera.object(type);
        if (type == "perspective") {
            projection.require("yfov");
            projection.require("znear");
            projection.number("aspectRatio", 0.0, kInfinity, true);
            projection.number("yfov", 0.0, kInfinity, true);
        } else {
            for (const char* key : {"xmag", "ymag", "zfar", "znear"})
                projection.require(key);
            projection.number("xmag", -kInfinity, kInfinity);
            projection.number("ymag", -kInfinity, kInfinity);
        }
        const double znear = *projection.number("znear", 0.0, kInfinity, type == "perspective");
        if (const auto zfar = projection.number("zfar", 0.0, kInfinity, true); zfar && *zfar <= znear)
            projection.fail("zfar", fmt::format("{} is not beyond znear {}", *zfar, znear));
    }
    const Fields root(file, file.root, "");
    const auto punctual = root.extension("KHR_lights_punctual");
    if (!punctual)
        return;
    for (const Fields& light : punctual->objects("lights")) {
        light.require("type");
        const std::string type = *light.oneOf("type", {"directional", "point", "spot"});
        light.numbers("color", 3, 0.0, 1.0);
        light.number("intensity", 0.0, kInfinity);
        light.number("range", 0.0, kInfinity, true);
        if (type == "spot") {
            light.require("spot");
            const Fields spot = *light.object("spot");
            const double inner = spot.number("innerConeAngle", 0.0, kHalfPi).value_or(0.0);
            const double outer = spot.number("outerConeAngle", 0.0, kHalfPi, true).value_or(std::numbers::pi / 4.0);
            if (inner >= outer)
                spot.fail("innerConeAngle", fmt::format("{} is not below outerConeAngle {}", inner, outer));
        }
    }
}

} // namespace penumbra::gltf
