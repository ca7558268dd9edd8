#include "GltfSchema.hpp"

#include "GltfLimits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <regex>
#include <set>

namespace penumbra::gltf {
namespace {

// The bufferView.target codes: ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER.
constexpr std::int64_t kArrayBuffer = 34962, kElementArrayBuffer = 34963;

void checkAsset(const JsonFile& file, const Fields& root)
{
    root.require("asset");
    const Fields asset = *root.object("asset");
    asset.require("version");
    for (const char* key : {"version", "minVersion"}) {
        const std::optional<std::string> version = asset.string(key);
        if (version && !std::regex_match(*version, std::regex("[0-9]+\\.[0-9]+")))
            asset.fail(key, fmt::format("expected a version like \"2.0\", got \"{}\"", *version));
    }
    if (asset.string("version")->rfind("2.", 0) != 0)
        asset.fail("version", fmt::format("glTF {} is not 2.x", *asset.string("version")));
    asset.string("generator");
    asset.string("copyright");
    (void)file;
}

// extensionsUsed lists every extension the file's objects carry (glTF 2.0, section 3.12).
void collectExtensions(const JsonFile& file, const Json& value, const std::string& pointer,
                       const std::set<std::string>& used)
{
    if (value.is_object()) {
        for (const auto& [key, child] : value.items()) {
            const std::string at = pointer + "/" + key;
            if (key == "extras")
                continue;
            if (key == "extensions" && child.is_object())
                for (const auto& [name, extension] : child.items())
                    if (!used.count(name))
                        file.fail(at + "/" + name, fmt::format("extension {} is not listed in extensionsUsed", name));
            collectExtensions(file, child, at, used);
        }
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i)
            collectExtensions(file, value[i], fmt::format("{}/{}", pointer, i), used);
    }
}

std::set<std::string> stringSet(const Fields& root, const char* key)
{
    std::set<std::string> out;
    if (!root.has(key))
        return out;
    const Json& value = root.json()[key];
    if (!value.is_array() || value.empty())
        root.fail(key, fmt::format("expected an array of at least 1 string, got {}", shortDump(value)));
    for (std::size_t i = 0; i < value.size(); ++i) {
        if (!value[i].is_string())
            root.fail(fmt::format("{}/{}", key, i), fmt::format("expected a string, got {}", shortDump(value[i])));
        if (!out.insert(value[i].get<std::string>()).second)
            root.fail(fmt::format("{}/{}", key, i), fmt::format("{} appears twice", value[i].get<std::string>()));
    }
    return out;
}

void checkExtensions(const JsonFile& file, const Fields& root)
{
    const std::set<std::string> used = stringSet(root, "extensionsUsed");
    const std::set<std::string> required = stringSet(root, "extensionsRequired");
    for (const std::string& name : required)
        if (!used.count(name))
            root.fail("extensionsRequired", fmt::format("{} is not listed in extensionsUsed", name));
    collectExtensions(file, file.root, "", used);
}

void checkBuffers(const JsonFile& file)
{
    for (const Fields& buffer : topLevel(file, "buffers")) {
        buffer.require("byteLength");
        buffer.string("uri");
        buffer.integer("byteLength", 1, kMaxInteger);
    }
    for (const Fields& view : topLevel(file, "bufferViews")) {
        view.require("buffer");
        view.require("byteLength");
        view.index("buffer", "buffers");
        view.integer("byteOffset", 0, kMaxInteger);
        view.integer("byteLength", 1, kMaxInteger);
        if (const auto stride = view.integer("byteStride", 4, 252); stride && *stride % 4 != 0)
            view.fail("byteStride", fmt::format("expected a multiple of 4, got {}", *stride));
        view.oneOf("target", {kArrayBuffer, kElementArrayBuffer});
    }
}

void checkAccessors(const JsonFile& file)
{
    for (const Fields& accessor : topLevel(file, "accessors")) {
        for (const char* key : {"componentType", "count", "type"})
            accessor.require(key);
        accessor.index("bufferView", "bufferViews");
        const auto offset = accessor.integer("byteOffset", 0, kMaxInteger);
        const std::int64_t component =
            *accessor.oneOf("componentType", {kByte, kUnsignedByte, kShort, kUnsignedShort, kUnsignedInt, kFloat});
        if (accessor.boolean("normalized").value_or(false) && (component == kFloat || component == kUnsignedInt))
            accessor.fail("normalized",
                          "only BYTE, UNSIGNED_BYTE, SHORT and UNSIGNED_SHORT components may be normalized");
        if (const auto count = accessor.integer("count", 1, kMaxInteger); std::uint64_t(*count) > kMaxAccessorElements)
            accessor.fail("count", fmt::format("{} elements, over the limit of {}", *count, kMaxAccessorElements));
        const std::string type = *accessor.oneOf("type", {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"});
        if (offset && !accessor.has("bufferView"))
            accessor.fail("byteOffset", "is only allowed with a bufferView");
        if (offset && *offset % componentSize(component) != 0)
            accessor.fail("byteOffset", fmt::format("{} is not a multiple of the component size {}", *offset,
                                                    componentSize(component)));
        accessor.numbers("min", componentCount(type));
        accessor.numbers("max", componentCount(type));
        if (accessor.has("sparse"))
            accessor.fail("sparse", "sparse accessors are not supported");
    }
}

struct AttributeFormat {
    std::vector<std::string_view> types;
    std::vector<std::int64_t> components; // normalized unless FLOAT
};

// glTF 2.0, section 3.7.2.1, table "Vertex attributes": the accessor formats of each semantic.
std::optional<AttributeFormat> attributeFormat(const std::string& semantic)
{
    const auto startsWith = [&](const char* prefix) { return semantic.rfind(prefix, 0) == 0; };
    if (semantic == "POSITION" || semantic == "NORMAL")
        return AttributeFormat{{"VEC3"}, {kFloat}};
    if (semantic == "TANGENT")
        return AttributeFormat{{"VEC4"}, {kFloat}};
    if (startsWith("TEXCOORD_"))
        return AttributeFormat{{"VEC2"}, {kFloat, kUnsignedByte, kUnsignedShort}};
    if (startsWith("COLOR_"))
        return AttributeFormat{{"VEC3", "VEC4"}, {kFloat, kUnsignedByte, kUnsignedShort}};
    if (startsWith("JOINTS_"))
        return AttributeFormat{{"VEC4"}, {kUnsignedByte, kUnsignedShort}};
    if (startsWith("WEIGHTS_"))
        return AttributeFormat{{"VEC4"}, {kFloat, kUnsignedByte, kUnsignedShort}};
    return std::nullopt;
}

bool indexedSemantic(const std::string& semantic)
{
    return std::regex_match(semantic, std::regex("(TEXCOORD|COLOR|JOINTS|WEIGHTS)_(0|[1-9][0-9]*)")) ||
           semantic == "POSITION" || semantic == "NORMAL" || semantic == "TANGENT";
}

void checkAttributeFormat(const JsonFile& file, const Fields& attributes, const std::string& semantic, int index)
{
    const Json& accessor = accessorJson(file, index);
    const std::string type = accessor["type"];
    const std::int64_t component = accessor["componentType"];
    const bool normalized = accessor.value("normalized", false);
    const AttributeFormat format = *attributeFormat(semantic);
    const bool ok =
        std::find(format.types.begin(), format.types.end(), type) != format.types.end() &&
        std::find(format.components.begin(), format.components.end(), component) != format.components.end() &&
        (component == kFloat || normalized || semantic.rfind("JOINTS_", 0) == 0);
    if (!ok)
        attributes.fail(semantic, fmt::format("accessor {} is {} of component type {}{}, which {} may not use", index,
                                              type, component, normalized ? " (normalized)" : "", semantic));
}

void checkPrimitive(const JsonFile& file, const Fields& primitive, AccessorUsage& usage)
{
    primitive.require("attributes");
    const Fields attributes = *primitive.object("attributes");
    std::optional<std::int64_t> count;
    for (const auto& [semantic, value] : attributes.json().items()) {
        if (!indexedSemantic(semantic) && semantic.rfind('_', 0) != 0)
            attributes.fail(semantic, "is not a glTF attribute semantic (application-specific ones start with '_')");
        const int index = *attributes.index(semantic, "accessors");
        if (attributeFormat(semantic))
            checkAttributeFormat(file, attributes, semantic, index);
        const std::int64_t elements = accessorJson(file, index)["count"];
        if (count && *count != elements)
            attributes.fail(semantic,
                            fmt::format("accessor {} has {} elements, other attributes {}", index, elements, *count));
        count = elements;
        if (const auto [used, fresh] = usage.emplace(index, "vertex attribute");
            !fresh && used->second != "vertex attribute")
            attributes.fail(semantic, fmt::format("accessor {} is also used as {}", index, used->second));
    }
    if (attributes.json().empty())
        file.fail(attributes.pointer(), "expected at least one attribute");
    for (const char* set : {"TEXCOORD_", "COLOR_", "JOINTS_", "WEIGHTS_"})
        for (int n = 1; attributes.has(fmt::format("{}{}", set, n)); ++n)
            if (!attributes.has(fmt::format("{}{}", set, n - 1)))
                attributes.fail(fmt::format("{}{}", set, n), fmt::format("{}{} is missing", set, n - 1));
    if (const auto position = attributes.index("POSITION", "accessors");
        position && !(accessorJson(file, *position).contains("min") && accessorJson(file, *position).contains("max")))
        file.deviations.add(kMissingBounds, fmt::format("/accessors/{}", *position));
    if (const auto indices = primitive.index("indices", "accessors")) {
        const Json& accessor = accessorJson(file, *indices);
        const std::int64_t component = accessor["componentType"];
        if (accessor["type"] != "SCALAR" ||
            (component != kUnsignedByte && component != kUnsignedShort && component != kUnsignedInt) ||
            accessor.value("normalized", false))
            primitive.fail("indices", fmt::format("accessor {} is not a SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or "
                                                  "UNSIGNED_INT",
                                                  *indices));
        if (const auto [used, fresh] = usage.emplace(*indices, "indices"); !fresh && used->second != "indices")
            primitive.fail("indices", fmt::format("accessor {} is also used as {}", *indices, used->second));
    }
    primitive.index("material", "materials");
    primitive.oneOf("mode", {0, 1, 2, 3, 4, 5, 6});
    if (primitive.has("targets")) {
        const Json& targets = primitive.json()["targets"];
        if (!targets.is_array() || targets.empty())
            primitive.fail("targets",
                           fmt::format("expected an array of at least 1 object, got {}", shortDump(targets)));
    }
}

AccessorUsage checkMeshes(const JsonFile& file)
{
    AccessorUsage usage;
    for (const Fields& mesh : topLevel(file, "meshes")) {
        mesh.require("primitives");
        for (const Fields& primitive : mesh.objects("primitives"))
            checkPrimitive(file, primitive, usage);
        if (mesh.has("weights") && (!mesh.json()["weights"].is_array() || mesh.json()["weights"].empty()))
            mesh.fail("weights",
                      fmt::format("expected an array of numbers, got {}", shortDump(mesh.json()["weights"])));
    }
    return usage;
}

void checkNodes(const JsonFile& file, const Fields& root, AccessorUsage& usage)
{
    const std::vector<Fields> nodes = topLevel(file, "nodes");
    std::vector<int> parent(nodes.size(), -1);
    std::uint64_t instances = 0;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        const Fields& node = nodes[n];
        node.index("camera", "cameras");
        const auto mesh = node.index("mesh", "meshes");
        if (node.index("skin", "skins") && !mesh)
            node.fail("skin", "a node with a skin needs a mesh");
        if (const auto matrix = node.numbers("matrix", 16)) {
            // glTF 2.0 section 3.5.3: a matrix MUST be decomposable to translation, rotation and scale, so its last
            // row (elements 3, 7, 11 and 15, column-major) is 0, 0, 0, 1; the renderer keeps the first three rows.
            const std::vector<double>& m = *matrix;
            if (std::abs(m[3]) > kAffineRowTolerance || std::abs(m[7]) > kAffineRowTolerance ||
                std::abs(m[11]) > kAffineRowTolerance || std::abs(m[15] - 1.0) > kAffineRowTolerance)
                node.fail("matrix", fmt::format("expected a last row (elements 3, 7, 11, 15) of 0, 0, 0, 1, as a "
                                                "matrix of translation, rotation and scale has, got {}, {}, {}, {}",
                                                m[3], m[7], m[11], m[15]));
        }
        node.numbers("translation", 3);
        node.numbers("scale", 3);
        if (const auto rotation = node.numbers("rotation", 4, -1.0, 1.0)) {
            const double length = std::sqrt((*rotation)[0] * (*rotation)[0] + (*rotation)[1] * (*rotation)[1] +
                                            (*rotation)[2] * (*rotation)[2] + (*rotation)[3] * (*rotation)[3]);
            if (std::abs(length - 1.0) > kUnitLengthTolerance)
                node.fail("rotation", fmt::format("expected a unit quaternion, got length {}", length));
        }
        if (node.has("matrix") && (node.has("translation") || node.has("rotation") || node.has("scale")))
            node.fail("matrix", "a node has either a matrix or translation, rotation and scale, not both");
        if (node.has("weights") && !mesh)
            node.fail("weights", "a node with weights needs a mesh");
        for (const int child : node.indices("children", "nodes")) {
            if (parent[std::size_t(child)] >= 0)
                node.fail("children",
                          fmt::format("node {} is already a child of node {}", child, parent[std::size_t(child)]));
            parent[std::size_t(child)] = int(n);
        }
        if (const auto light = node.extension("KHR_lights_punctual")) {
            light->require("light");
            const std::size_t lights =
                file.root.contains("extensions") && file.root["extensions"].is_object() &&
                        file.root["extensions"].contains("KHR_lights_punctual")
                    ? file.root["extensions"]["KHR_lights_punctual"].value("lights", Json::array()).size()
                    : 0;
            const Json& index = light->json()["light"];
            if (!index.is_number_integer() || index.get<std::int64_t>() < 0 ||
                std::size_t(index.get<std::int64_t>()) >= lights)
                light->fail("light", fmt::format("expected an index of KHR_lights_punctual lights (the file has {}), "
                                                 "got {}",
                                                 lights, shortDump(index)));
        }
        instances += checkInstancing(file, node, usage);
        if (instances > kMaxInstances)
            file.fail(node.pointerOf("extensions") + "/EXT_mesh_gpu_instancing",
                      fmt::format("the file's instanced nodes reach {} instances here, over the limit of {}", instances,
                                  kMaxInstances));
    }
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        std::size_t steps = 0;
        for (int at = parent[n]; at >= 0; at = parent[std::size_t(at)]) {
            if (++steps > nodes.size())
                file.fail(fmt::format("/nodes/{}", n), "the node is its own ancestor");
            if (steps >= kMaxNodeDepth)
                file.fail(fmt::format("/nodes/{}", n),
                          fmt::format("the node is {} levels deep, over the limit of {}", steps + 1, kMaxNodeDepth));
        }
    }
    for (const Fields& scene : topLevel(file, "scenes"))
        for (const int node : scene.indices("nodes", "nodes"))
            if (parent[std::size_t(node)] >= 0)
                scene.fail("nodes",
                           fmt::format("node {} is a child of node {}, not a root", node, parent[std::size_t(node)]));
    if (root.has("scene") && !root.has("scenes"))
        root.fail("scene", "the file has no scenes");
    root.index("scene", "scenes");
}

} // namespace

std::int64_t componentSize(std::int64_t componentType)
{
    switch (componentType) {
    case kByte:
    case kUnsignedByte:
        return 1;
    case kShort:
    case kUnsignedShort:
        return 2;
    default:
        return 4;
    }
}

std::size_t componentCount(const std::string& type)
{
    if (type == "SCALAR")
        return 1;
    if (type == "MAT2")
        return 4;
    if (type == "MAT3")
        return 9;
    if (type == "MAT4")
        return 16;
    return std::size_t(type.back() - '0'); // VEC2, VEC3, VEC4
}

std::vector<Fields> topLevel(const JsonFile& file, std::string_view name)
{
    const Fields root(file, file.root, "");
    return root.objects(name);
}

void checkSchema(const JsonFile& file)
{
    const Fields root(file, file.root, "");
    checkAsset(file, root);
    checkExtensions(file, root);
    checkBuffers(file);
    checkAccessors(file);
    checkTexturesAndImages(file);
    checkMaterials(file);
    AccessorUsage usage = checkMeshes(file);
    checkCamerasAndLights(file);
    checkNodes(file, root, usage);
    checkSkinsAndAnimations(file);
}

const Json& accessorJson(const JsonFile& file, int index) { return file.root["accessors"][std::size_t(index)]; }

} // namespace penumbra::gltf
