#include "GltfBuilder.hpp"

#include "penumbra/imageio/ImageFiles.hpp"

#include <fmt/format.h>
#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace penumbra::testing {
namespace {

std::string base64(std::span<const std::uint8_t> bytes)
{
    static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t chunk = (std::uint32_t(bytes[i]) << 16) |
                                    (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0u) |
                                    (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0u);
        out += digits[(chunk >> 18) & 63];
        out += digits[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[chunk & 63] : '=';
    }
    return out;
}

void writeFile(const std::filesystem::path& path, std::span<const std::uint8_t> bytes)
{
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out)
        throw std::runtime_error("cannot write " + path.string());
}

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t value)
{
    for (int i = 0; i < 4; ++i)
        out.push_back(std::uint8_t(value >> (8 * i)));
}

std::vector<std::uint8_t> encodePng(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba)
{
    penumbra::rhi::Image image{width, height, penumbra::rhi::Format::RGBA8, {}};
    const auto* first = reinterpret_cast<const std::byte*>(rgba.data());
    image.bytes.assign(first, first + rgba.size());
    const std::string png = penumbra::imageio::encodePng(image);
    return {png.begin(), png.end()};
}

} // namespace

GltfBuilder::GltfBuilder()
    : json_({{"asset", {{"version", "2.0"}, {"generator", "penumbra tests"}}},
             {"scene", 0},
             {"scenes", {{{"nodes", nlohmann::json::array()}}}}})
{
}

int GltfBuilder::add(const std::string& array, nlohmann::json element)
{
    nlohmann::json& items = json_[array];
    if (items.is_null())
        items = nlohmann::json::array();
    items.push_back(std::move(element));
    return int(items.size()) - 1;
}

void GltfBuilder::addRoot(int node) { json_["scenes"][0]["nodes"].push_back(node); }

void GltfBuilder::useExtension(const std::string& name, bool required)
{
    const auto list = [&](const char* key) {
        nlohmann::json& names = json_[key];
        if (names.is_null())
            names = nlohmann::json::array();
        if (std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
    };
    list("extensionsUsed");
    if (required)
        list("extensionsRequired");
}

int GltfBuilder::addView(std::span<const std::uint8_t> bytes)
{
    while (bin_.size() % 4 != 0)
        bin_.push_back(0);
    const std::size_t offset = bin_.size();
    bin_.insert(bin_.end(), bytes.begin(), bytes.end());
    return add("bufferViews", {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}});
}

int GltfBuilder::addAccessor(std::span<const std::uint8_t> bytes, std::size_t count, const std::string& type,
                             Component component, bool normalized)
{
    nlohmann::json accessor = {{"bufferView", addView(bytes)},
                               {"count", count},
                               {"type", type},
                               {"componentType", int(component)}};
    if (normalized)
        accessor["normalized"] = true;
    return add("accessors", accessor);
}

int GltfBuilder::addPositions(std::span<const glm::vec3> values)
{
    glm::vec3 lo(values.front()), hi(values.front());
    for (const glm::vec3& v : values) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    const int accessor = addAccessor(bytesOf(values), values.size(), "VEC3", Component::Float);
    json_["accessors"][std::size_t(accessor)]["min"] = {lo.x, lo.y, lo.z};
    json_["accessors"][std::size_t(accessor)]["max"] = {hi.x, hi.y, hi.z};
    return accessor;
}

int GltfBuilder::addNormals(std::span<const glm::vec3> values)
{
    return addAccessor(bytesOf(values), values.size(), "VEC3", Component::Float);
}

int GltfBuilder::addUvs(std::span<const glm::vec2> values)
{
    return addAccessor(bytesOf(values), values.size(), "VEC2", Component::Float);
}

int GltfBuilder::addIndices(std::span<const std::uint32_t> values, Component component)
{
    std::vector<std::uint8_t> bytes;
    for (const std::uint32_t v : values) {
        if (component == Component::UnsignedByte) {
            bytes.push_back(std::uint8_t(v));
        } else if (component == Component::UnsignedShort) {
            const auto s = std::uint16_t(v);
            bytes.insert(bytes.end(), {std::uint8_t(s & 0xff), std::uint8_t(s >> 8)});
        } else {
            appendU32(bytes, v);
        }
    }
    return addAccessor(bytes, values.size(), "SCALAR", component);
}

int GltfBuilder::addPngImage(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba)
{
    const std::vector<std::uint8_t> png = encodePng(width, height, rgba);
    return add("images", {{"bufferView", addView(png)}, {"mimeType", "image/png"}});
}

nlohmann::json GltfBuilder::withBuffer(const std::string& uri) const
{
    nlohmann::json document = json_;
    nlohmann::json buffer = {{"byteLength", bin_.size()}};
    if (!uri.empty())
        buffer["uri"] = uri;
    document["buffers"] = nlohmann::json::array({buffer});
    return document;
}

nlohmann::json GltfBuilder::embedded() const
{
    return withBuffer("data:application/octet-stream;base64," + base64(bin_));
}

void GltfBuilder::writeGltf(const std::filesystem::path& path, bool externalBuffer) const
{
    nlohmann::json document = embedded();
    if (externalBuffer) {
        const std::string uri = path.stem().string() + ".bin";
        writeFile(path.parent_path() / uri, bin_);
        document = withBuffer(uri);
    }
    const std::string text = document.dump(1);
    writeFile(path, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

std::vector<std::uint8_t> GltfBuilder::glbBytes() const
{
    std::string text = withBuffer("").dump();
    while (text.size() % 4 != 0)
        text += ' ';
    std::vector<std::uint8_t> bin = bin_;
    while (bin.size() % 4 != 0)
        bin.push_back(0);
    std::vector<std::uint8_t> out;
    appendU32(out, 0x46546C67); // "glTF"
    appendU32(out, 2);
    appendU32(out, std::uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    appendU32(out, std::uint32_t(text.size()));
    appendU32(out, 0x4E4F534A); // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    appendU32(out, std::uint32_t(bin.size()));
    appendU32(out, 0x004E4942); // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

void GltfBuilder::writeGlb(const std::filesystem::path& path) const { writeFile(path, glbBytes()); }

GltfBuilder sampledTexturesScene(const std::vector<nlohmann::json>& samplers)
{
    GltfBuilder b;
    std::vector<std::uint8_t> rgba;
    for (std::uint8_t i = 0; i < 16; ++i)
        rgba.insert(rgba.end(), {std::uint8_t(i * 16), 128, std::uint8_t(255 - i * 16), 255});
    const int image = b.addPngImage(4, 4, rgba);
    for (std::size_t i = 0; i < samplers.size(); ++i) {
        nlohmann::json texture = {{"source", image}};
        if (!samplers[i].is_null())
            texture["sampler"] = b.add("samplers", samplers[i]);
        const int material =
            b.add("materials",
                  {{"name", "material " + std::to_string(i)},
                   {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", b.add("textures", texture)}}}}}});
        b.addRoot(b.add("nodes", {{"name", "cube " + std::to_string(i)},
                                  {"mesh", addCubeMesh(b, "cube " + std::to_string(i), material)},
                                  {"translation", {3.0 * double(i), 0, 0}}}));
    }
    return b;
}

int addInstancedNode(GltfBuilder& builder, nlohmann::json node, const InstanceAttributes& instances)
{
    nlohmann::json attributes = nlohmann::json::object();
    if (!instances.translations.empty())
        attributes["TRANSLATION"] = builder.addAccessor(bytesOf(std::span<const glm::vec3>(instances.translations)),
                                                        instances.translations.size(), "VEC3", Component::Float);
    if (!instances.rotations.empty()) {
        const std::span<const glm::vec4> rotations(instances.rotations);
        if (instances.rotationComponent == Component::Float) {
            attributes["ROTATION"] =
                builder.addAccessor(bytesOf(rotations), rotations.size(), "VEC4", Component::Float);
        } else {
            // glTF 2.0 section 3.11: c = round(f * 127) for BYTE, round(f * 32767) for SHORT.
            const bool bytes = instances.rotationComponent == Component::Byte;
            std::vector<std::uint8_t> encoded;
            for (const glm::vec4& rotation : rotations)
                for (int c = 0; c < 4; ++c) {
                    const auto value = std::int16_t(std::lround(rotation[c] * (bytes ? 127.0f : 32767.0f)));
                    encoded.push_back(std::uint8_t(value & 0xff));
                    if (!bytes)
                        encoded.push_back(std::uint8_t((value >> 8) & 0xff));
                }
            attributes["ROTATION"] =
                builder.addAccessor(encoded, rotations.size(), "VEC4", instances.rotationComponent, true);
        }
    }
    if (!instances.scales.empty())
        attributes["SCALE"] = builder.addAccessor(bytesOf(std::span<const glm::vec3>(instances.scales)),
                                                  instances.scales.size(), "VEC3", Component::Float);
    node["extensions"]["EXT_mesh_gpu_instancing"] = {{"attributes", attributes}};
    builder.useExtension("EXT_mesh_gpu_instancing", true);
    return builder.add("nodes", std::move(node));
}

int addCubeMesh(GltfBuilder& builder, const std::string& name, int material, Component indexComponent)
{
    // Per face: normal, and the two in-face axes u and v with u x v = normal (counter-clockwise outside).
    const std::array<std::array<glm::vec3, 3>, 6> faces = {{{{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}},
                                                            {{{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}},
                                                            {{{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}},
                                                            {{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}},
                                                            {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}},
                                                            {{{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}}}};
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
    for (const auto& [n, u, v] : faces) {
        const auto base = std::uint32_t(positions.size());
        for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            positions.push_back(n + corner.x * u + corner.y * v);
            normals.push_back(n);
            uvs.push_back(glm::vec2(0.5f * (corner.x + 1.0f), 0.5f * (1.0f - corner.y)));
        }
        indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    nlohmann::json primitive = {{"attributes",
                                 {{"POSITION", builder.addPositions(positions)},
                                  {"NORMAL", builder.addNormals(normals)},
                                  {"TEXCOORD_0", builder.addUvs(uvs)}}},
                                {"indices", builder.addIndices(indices, indexComponent)}};
    if (material >= 0)
        primitive["material"] = material;
    return builder.add("meshes", {{"name", name}, {"primitives", {primitive}}});
}

int addQuadMesh(GltfBuilder& builder, const std::string& name, int material, const QuadAttributes& attributes)
{
    const std::array<glm::vec3, 4> positions{{{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}}};
    const std::array<glm::vec3, 4> normals{{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}}};
    const std::array<glm::vec2, 4> uvs{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    const std::array<std::uint32_t, 6> indices{0, 3, 2, 0, 2, 1};
    nlohmann::json attributeJson = {{"POSITION", builder.addPositions(positions)},
                                    {"NORMAL", builder.addNormals(normals)},
                                    {"TEXCOORD_0", builder.addUvs(uvs)}};
    if (attributes.mirroredUv1) {
        std::array<glm::vec2, 4> mirrored{};
        for (std::size_t i = 0; i < uvs.size(); ++i)
            mirrored[i] = {1.0f - uvs[i].x, uvs[i].y};
        attributeJson["TEXCOORD_1"] = builder.addUvs(mirrored);
    }
    if (const auto color = attributes.color) {
        if (color->a == 1.0f) {
            // Vertex attributes start on 4-byte boundaries (glTF 2.0, section 3.6.2.4): 3 bytes and a pad byte each.
            std::vector<std::uint8_t> bytes;
            for (std::size_t i = 0; i < positions.size(); ++i) {
                for (int c = 0; c < 3; ++c)
                    bytes.push_back(std::uint8_t(std::lround((*color)[c] * 255.0f)));
                bytes.push_back(0);
            }
            const int accessor = builder.addAccessor(bytes, positions.size(), "VEC3", Component::UnsignedByte, true);
            builder.json()["bufferViews"][builder.json()["accessors"][std::size_t(accessor)]["bufferView"]
                                              .get<std::size_t>()]["byteStride"] = 4;
            attributeJson["COLOR_0"] = accessor;
        } else {
            const std::array<glm::vec4, 4> colors{*color, *color, *color, *color};
            attributeJson["COLOR_0"] = builder.addAccessor(bytesOf(std::span<const glm::vec4>(colors)), colors.size(),
                                                           "VEC4", Component::Float);
        }
    }
    if (const auto tangent = attributes.tangent) {
        const std::array<glm::vec4, 4> tangents{*tangent, *tangent, *tangent, *tangent};
        attributeJson["TANGENT"] = builder.addAccessor(bytesOf(std::span<const glm::vec4>(tangents)), tangents.size(),
                                                       "VEC4", Component::Float);
    }
    nlohmann::json primitive = {{"attributes", attributeJson},
                                {"indices", builder.addIndices(indices, Component::UnsignedShort)}};
    if (material >= 0)
        primitive["material"] = material;
    return builder.add("meshes", {{"name", name}, {"primitives", {primitive}}});
}

int addTextureRow(GltfBuilder& builder, std::span<const std::array<std::uint8_t, 4>> texels)
{
    std::vector<std::uint8_t> rgba;
    for (const auto& texel : texels)
        rgba.insert(rgba.end(), texel.begin(), texel.end());
    return builder.add("textures", {{"source", builder.addPngImage(std::uint32_t(texels.size()), 1, rgba)}});
}

GltfBuilder exampleScene()
{
    GltfBuilder b;
    const int ground =
        b.add("materials",
              {{"name", "ground"},
               {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.75, 1.0}}, {"metallicFactor", 0.0}}}});
    const int red =
        b.add("materials",
              {{"name", "red"},
               {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.1, 0.1, 1.0}}, {"metallicFactor", 0.0}}}});
    const int mask =
        b.add("materials",
              {{"name", "mask"},
               {"alphaMode", "MASK"},
               {"alphaCutoff", 0.4},
               {"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.6, 0.1, 1.0}}, {"metallicFactor", 0.0}}}});
    const int blend =
        b.add("materials",
              {{"name", "blend"},
               {"alphaMode", "BLEND"},
               {"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.2, 0.8, 0.5}}, {"metallicFactor", 0.0}}}});
    const int groundMesh = addCubeMesh(b, "ground", ground);
    const int cube = addCubeMesh(b, "cube", red, Component::UnsignedByte);
    const int maskCube = addCubeMesh(b, "mask cube", mask, Component::UnsignedInt);
    const int blendCube = addCubeMesh(b, "blend cube", blend);
    b.addRoot(b.add("nodes",
                    {{"name", "ground"}, {"mesh", groundMesh}, {"translation", {0, -0.1, 0}}, {"scale", {8, 0.1, 8}}}));
    // A parent that moves and turns its children: the cubes' world transforms come from the hierarchy.
    const int standing = b.add("nodes", {{"name", "standing cube"}, {"mesh", cube}, {"translation", {0, 1, 0}}});
    const int floating = b.add("nodes", {{"name", "floating cube"},
                                         {"mesh", maskCube},
                                         {"translation", {2.5, 2, 0}},
                                         {"rotation", {0, 0.3826834, 0, 0.9238795}},
                                         {"scale", {0.5, 1.5, 0.5}}});
    const int glass = b.add("nodes", {{"name", "blend cube"},
                                      {"mesh", blendCube},
                                      {"translation", {-2.5, 0.75, 1}},
                                      {"scale", {0.75, 0.75, 0.75}}});
    b.addRoot(
        b.add("nodes", {{"name", "cubes"}, {"translation", {0, 0, -1}}, {"children", {standing, floating, glass}}}));

    b.json()["extensionsUsed"] = {"KHR_lights_punctual"};
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"intensity", 2.5}},
        {{"name", "spot"},
         {"type", "spot"},
         {"intensity", 20.0},
         {"range", 12.0},
         {"color", {1.0, 0.9, 0.7}},
         {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.5}}}},
        {{"name", "bulb"}, {"type", "point"}, {"intensity", 5.0}}};
    // The sun 50 degrees below the horizon (rotation about x, then turned about y).
    b.addRoot(b.add("nodes", {{"name", "sun"},
                              {"rotation", {-0.4082179, 0.2345697, 0.1093817, 0.8754261}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
    b.addRoot(b.add("nodes", {{"name", "spot"},
                              {"translation", {0, 6, 0}},
                              {"rotation", {-0.7071068, 0, 0, 0.7071068}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}));
    b.addRoot(b.add("nodes", {{"name", "bulb"},
                              {"translation", {-3, 3, 3}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}}));

    b.add("cameras", {{"name", "overview"},
                      {"type", "perspective"},
                      {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 60.0}}}});
    // At (0, 5, 9), pitched down about 30 degrees towards the cubes.
    b.addRoot(b.add("nodes", {{"name", "overview camera"},
                              {"camera", 0},
                              {"translation", {0, 5, 9}},
                              {"rotation", {-0.2588190, 0, 0, 0.9659258}}}));
    return b;
}

GltfBuilder materialsScene()
{
    GltfBuilder b;
    using Texel = std::array<std::uint8_t, 4>;
    const std::array<Texel, 2> redGreen{{{230, 30, 30, 255}, {30, 230, 30, 255}}};
    const std::array<Texel, 2> metalRough{{{0, 255, 0, 255}, {0, 60, 255, 255}}};
    const std::array<Texel, 2> tilted{{{204, 128, 230, 255}, {128, 204, 230, 255}}};
    const std::array<Texel, 2> halves{{{255, 255, 255, 255}, {40, 40, 40, 255}}};
    const auto factors = [](double r, double g, double bl, double a = 1.0) {
        return nlohmann::json{{"baseColorFactor", {r, g, bl, a}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.6}};
    };
    const int ground = b.add("materials", {{"name", "ground"}, {"pbrMetallicRoughness", factors(0.8, 0.8, 0.75)}});
    const int twoSided =
        b.add("materials",
              {{"name", "double-sided"}, {"doubleSided", true}, {"pbrMetallicRoughness", factors(0.8, 0.2, 0.2)}});
    const int white = b.add("materials", {{"name", "white"}, {"pbrMetallicRoughness", factors(1, 1, 1)}});
    nlohmann::json metal = factors(0.9, 0.6, 0.2);
    metal["metallicFactor"] = 1.0;
    metal["roughnessFactor"] = 1.0;
    metal["metallicRoughnessTexture"] = {{"index", addTextureRow(b, metalRough)}};
    const int metallic = b.add("materials", {{"name", "metal-rough"}, {"pbrMetallicRoughness", metal}});
    const int bumpy = b.add("materials", {{"name", "normal"},
                                          {"pbrMetallicRoughness", factors(0.7, 0.7, 0.9)},
                                          {"normalTexture", {{"index", addTextureRow(b, tilted)}, {"scale", 1.0}}}});
    const int glowing =
        b.add("materials", {{"name", "occlusion-emissive"},
                            {"pbrMetallicRoughness", factors(0.5, 0.5, 0.5)},
                            {"occlusionTexture", {{"index", addTextureRow(b, halves)}, {"strength", 1.0}}},
                            {"emissiveTexture", {{"index", addTextureRow(b, halves)}}},
                            {"emissiveFactor", {0.2, 0.6, 1.0}},
                            {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1.5}}}}}});
    nlohmann::json transformed = factors(1, 1, 1);
    transformed["baseColorTexture"] = {{"index", addTextureRow(b, redGreen)},
                                       {"texCoord", 1},
                                       {"extensions",
                                        {{"KHR_texture_transform",
                                          {{"offset", {0.5, 0.0}}, {"rotation", 0.3}, {"scale", {2.0, 1.0}}}}}}};
    const int moved = b.add("materials", {{"name", "transform-texcoord1"}, {"pbrMetallicRoughness", transformed}});
    const int unlit = b.add("materials", {{"name", "unlit"},
                                          {"pbrMetallicRoughness", factors(0.9, 0.5, 0.1)},
                                          {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}});
    const int glassRed =
        b.add("materials",
              {{"name", "glass red"}, {"alphaMode", "BLEND"}, {"pbrMetallicRoughness", factors(0.9, 0.1, 0.1, 0.5)}});
    const int glassBlue = b.add("materials", {{"name", "glass blue"},
                                              {"alphaMode", "BLEND"},
                                              {"doubleSided", true},
                                              {"pbrMetallicRoughness", factors(0.1, 0.2, 0.9, 0.5)}});
    b.json()["extensionsUsed"] = {"KHR_materials_emissive_strength", "KHR_texture_transform", "KHR_materials_unlit"};

    b.addRoot(b.add("nodes", {{"name", "ground"},
                              {"mesh", addCubeMesh(b, "ground", ground)},
                              {"translation", {0, -0.1, 0}},
                              {"scale", {10, 0.1, 6}}}));
    const auto quad = [&](const std::string& name, int mesh, double x, double y, double z, double yaw = 0.0) {
        b.addRoot(b.add("nodes", {{"name", name},
                                  {"mesh", mesh},
                                  {"translation", {x, y, z}},
                                  {"rotation", {0.0, std::sin(0.5 * yaw), 0.0, std::cos(0.5 * yaw)}},
                                  {"scale", {0.8, 0.8, 0.8}}}));
    };
    quad("double-sided", addQuadMesh(b, "double-sided", twoSided), -6, 1, 0, 3.14159265);
    quad("vertex colours", addQuadMesh(b, "vertex colours", white, {.color = glm::vec4(0.2f, 0.9f, 0.3f, 1.0f)}), -4, 1,
         0);
    quad("metal-rough", addQuadMesh(b, "metal-rough", metallic), -2, 1, 0);
    quad("normal with tangents", addQuadMesh(b, "normal with tangents", bumpy, {.tangent = glm::vec4(1, 0, 0, 1)}), 0,
         1, 0);
    quad("normal without tangents", addQuadMesh(b, "normal without tangents", bumpy), 2, 1, 0);
    quad("occlusion-emissive", addQuadMesh(b, "occlusion-emissive", glowing), 4, 1, 0);
    quad("transform-texcoord1", addQuadMesh(b, "transform-texcoord1", moved, {.mirroredUv1 = true}), 6, 1, 0);
    quad("unlit", addQuadMesh(b, "unlit", unlit), -3, 1, 2.5);
    quad("glass red", addQuadMesh(b, "glass red", glassRed), 2.5, 0.9, 2.5);
    quad("glass blue", addQuadMesh(b, "glass blue", glassBlue), 3.1, 1.3, 3.0);

    b.json()["extensionsUsed"].push_back("KHR_lights_punctual");
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"intensity", 2.5}}};
    // Behind the camera's right shoulder, 40 degrees up: the fronts of the quads and the ground are lit.
    b.addRoot(b.add("nodes", {{"name", "sun"},
                              {"rotation", {-0.3265056, 0.2126311, 0.0761205, 0.9178247}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
    b.add("cameras", {{"name", "materials"},
                      {"type", "perspective"},
                      {"perspective", {{"yfov", 0.7}, {"znear", 0.1}, {"zfar", 60.0}}}});
    b.addRoot(b.add("nodes", {{"name", "materials camera"},
                              {"camera", 0},
                              {"translation", {0, 3, 13}},
                              {"rotation", {-0.0871557, 0, 0, 0.9961947}}}));
    return b;
}

int addSphereMesh(GltfBuilder& builder, const std::string& name, int material, int segments, int rings)
{
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
    const float pi = 3.14159265f;
    for (int r = 0; r <= rings; ++r) {
        const float polar = pi * float(r) / float(rings);
        for (int s = 0; s <= segments; ++s) {
            const float around = 2.0f * pi * float(s) / float(segments);
            positions.emplace_back(std::sin(polar) * std::sin(around), std::cos(polar),
                                   std::sin(polar) * std::cos(around));
            uvs.emplace_back(float(s) / float(segments), float(r) / float(rings));
        }
    }
    const auto vertex = [segments](int r, int s) { return std::uint32_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            // Seen from outside, +polar is down and +around is to the right: (r, s), (r + 1, s), (r + 1, s + 1) is
            // counter-clockwise.
            if (r > 0)
                indices.insert(indices.end(), {vertex(r, s), vertex(r + 1, s), vertex(r, s + 1)});
            if (r + 1 < rings)
                indices.insert(indices.end(), {vertex(r, s + 1), vertex(r + 1, s), vertex(r + 1, s + 1)});
        }
    nlohmann::json primitive = {{"attributes",
                                 {{"POSITION", builder.addPositions(positions)},
                                  {"NORMAL", builder.addNormals(positions)},
                                  {"TEXCOORD_0", builder.addUvs(uvs)}}},
                                {"indices", builder.addIndices(indices, Component::UnsignedShort)}};
    if (material >= 0)
        primitive["material"] = material;
    return builder.add("meshes", {{"name", name}, {"primitives", {primitive}}});
}

GltfBuilder metallicSpheresScene()
{
    GltfBuilder b;
    const int ground =
        b.add("materials",
              {{"name", "ground"},
               {"pbrMetallicRoughness",
                {{"baseColorFactor", {0.6, 0.6, 0.6, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}}});
    b.addRoot(b.add("nodes", {{"name", "ground"},
                              {"mesh", addCubeMesh(b, "ground", ground)},
                              {"translation", {0, -0.5, 0}},
                              {"scale", {3.2, 0.05, 2.4}}}));
    struct Row {
        const char* name;
        std::array<double, 3> color;
        double metallic;
    };
    const std::array<Row, 4> rows{{{"gold", {1.0, 0.77, 0.34}, 1.0},
                                   {"silver", {0.97, 0.96, 0.91}, 1.0},
                                   {"copper", {0.96, 0.64, 0.54}, 1.0},
                                   {"white", {0.9, 0.9, 0.9}, 0.0}}};
    constexpr int kColumns = 5;
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (int c = 0; c < kColumns; ++c) {
            const double roughness = 0.1 + 0.2 * c;
            const std::string name = fmt::format("{} {:.1f}", rows[r].name, roughness);
            const int material =
                b.add("materials", {{"name", name},
                                    {"pbrMetallicRoughness",
                                     {{"baseColorFactor", {rows[r].color[0], rows[r].color[1], rows[r].color[2], 1.0}},
                                      {"metallicFactor", rows[r].metallic},
                                      {"roughnessFactor", roughness}}}});
            b.addRoot(b.add("nodes", {{"name", name},
                                      {"mesh", addSphereMesh(b, name, material)},
                                      {"translation", {1.2 * (c - 2), 0.0, 1.2 * (double(r) - 1.5)}},
                                      {"scale", {0.45, 0.45, 0.45}}}));
        }
    return b;
}

GltfBuilder missingImageScene()
{
    GltfBuilder b;
    const int image = b.add("images", {{"uri", "textures/albedo.png"}});
    const int texture = b.add("textures", {{"source", image}});
    const int material = b.add("materials", {{"name", "painted"},
                                             {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}});
    b.addRoot(b.add("nodes", {{"name", "cube"}, {"mesh", addCubeMesh(b, "cube", material)}}));
    return b;
}

std::string truncatedGltf(const GltfBuilder& builder, double keep)
{
    const std::string text = builder.embedded().dump(1);
    const std::size_t uri = text.find("data:application/octet-stream;base64,");
    const std::size_t end = text.find('"', uri);
    return text.substr(0, uri + std::size_t(keep * double(end - uri)));
}

GltfBuilder largeTexturesScene(int count, std::uint32_t side)
{
    GltfBuilder b;
    std::uint32_t state = 12345;
    // Numerical Recipes' linear congruential generator (section 7.1): deterministic noise without <random>.
    const auto next = [&state] { return state = state * 1664525u + 1013904223u; };
    const auto picture = [&](std::uint8_t blue) {
        std::vector<std::uint8_t> rgba(std::size_t(side) * side * 4);
        for (std::size_t i = 0; i < rgba.size(); i += 4) {
            const std::uint32_t noise = next() >> 24;
            const std::uint32_t x = std::uint32_t(i / 4) % side;
            rgba[i] = std::uint8_t((x * 255 / side + noise) / 2);
            rgba[i + 1] = std::uint8_t(noise);
            rgba[i + 2] = blue;
            rgba[i + 3] = 255;
        }
        return b.add("textures", {{"source", b.addPngImage(side, side, rgba)}});
    };
    for (int i = 0; i < count; ++i) {
        const int material =
            b.add("materials", {{"name", fmt::format("textured {}", i)},
                                {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", picture(0)}}}}},
                                {"normalTexture", {{"index", picture(255)}}}});
        b.addRoot(b.add("nodes", {{"name", fmt::format("cube {}", i)},
                                  {"mesh", addCubeMesh(b, fmt::format("cube {}", i), material)},
                                  {"translation", {2.5 * i, 1.0, 0.0}}}));
    }
    return b;
}

} // namespace penumbra::testing
