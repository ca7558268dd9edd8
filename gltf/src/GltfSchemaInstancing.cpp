#include "GltfSchema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace penumbra::gltf {
namespace {

struct InstanceFormat {
    std::string_view type;
    std::vector<std::int64_t> components; // normalized unless FLOAT
};

// EXT_mesh_gpu_instancing, "Extending Nodes With Instance Attributes": the accessor type and component types of
// each attribute. Application-specific attributes (a leading '_') have no format.
std::optional<InstanceFormat> instanceFormat(const std::string& name)
{
    if (name == "TRANSLATION" || name == "SCALE")
        return InstanceFormat{"VEC3", {kFloat}};
    if (name == "ROTATION")
        return InstanceFormat{"VEC4", {kFloat, kByte, kShort}};
    return std::nullopt;
}

void checkFormat(const JsonFile& file, const Fields& attributes, const std::string& name, int index)
{
    const std::optional<InstanceFormat> format = instanceFormat(name);
    if (!format)
        return;
    const Json& accessor = file.root["accessors"][std::size_t(index)];
    const std::string type = accessor["type"];
    const std::int64_t component = accessor["componentType"];
    const bool normalized = accessor.value("normalized", false);
    const bool ok =
        type == format->type &&
        std::find(format->components.begin(), format->components.end(), component) != format->components.end() &&
        (component == kFloat || normalized);
    if (!ok)
        attributes.fail(name, fmt::format("accessor {} is {} of component type {}{}, which {} may not use", index, type,
                                          component, normalized ? " (normalized)" : "", name));
}

} // namespace

std::uint64_t checkInstancing(const JsonFile& file, const Fields& node, AccessorUsage& usage)
{
    const std::optional<Fields> extension = node.extension("EXT_mesh_gpu_instancing");
    if (!extension)
        return 0;
    // The extension: "Instancing only applies to mesh nodes, there is no defined behavior for a node with this
    // extension that doesn't also have a mesh."
    if (!node.has("mesh"))
        file.fail(extension->pointer(), "the node has no mesh to instance");
    extension->require("attributes");
    const Fields attributes = *extension->object("attributes");
    if (attributes.json().empty())
        file.fail(attributes.pointer(), "expected at least one attribute");
    std::optional<std::int64_t> count;
    for (const auto& [name, value] : attributes.json().items()) {
        if (!instanceFormat(name) && name.rfind('_', 0) != 0)
            attributes.fail(name, "is not an EXT_mesh_gpu_instancing attribute (TRANSLATION, ROTATION, SCALE; "
                                  "application-specific ones start with '_')");
        const int index = *attributes.index(name, "accessors");
        checkFormat(file, attributes, name, index);
        // The extension: "All attribute accessors in a given node must have the same count."
        const std::int64_t elements = file.root["accessors"][std::size_t(index)]["count"];
        if (count && *count != elements)
            attributes.fail(name,
                            fmt::format("accessor {} has {} elements, other attributes {}", index, elements, *count));
        count = elements;
        if (const auto [used, fresh] = usage.emplace(index, "instance attribute");
            !fresh && used->second != "instance attribute")
            attributes.fail(name, fmt::format("accessor {} is also used as {}", index, used->second));
    }
    return std::uint64_t(*count);
}

} // namespace penumbra::gltf
