#include "GltfLayout.hpp"

#include "GltfLimits.hpp"
#include "GltfSchema.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

namespace penumbra::gltf {
namespace {

std::uint64_t unsignedOf(const Json& object, const char* key, std::uint64_t fallback = 0)
{
    return object.contains(key) ? object[key].get<std::uint64_t>() : fallback;
}

void checkBufferLayout(const JsonFile& file, const tinygltf::Model& model)
{
    for (std::size_t b = 0; b < file.count("buffers"); ++b) {
        const std::uint64_t declared = unsignedOf(file.root["buffers"][b], "byteLength");
        if (declared > kMaxBufferBytes)
            file.fail(fmt::format("/buffers/{}/byteLength", b),
                      fmt::format("{} bytes, over the limit of {}", declared, kMaxBufferBytes));
        const std::size_t actual = b < model.buffers.size() ? model.buffers[b].data.size() : 0;
        if (actual < declared)
            file.fail(fmt::format("/buffers/{}/byteLength", b),
                      fmt::format("{} bytes declared, the buffer's data has {}", declared, actual));
    }
    for (std::size_t v = 0; v < file.count("bufferViews"); ++v) {
        const Json& view = file.root["bufferViews"][v];
        const std::uint64_t buffer = unsignedOf(view, "buffer");
        const std::uint64_t size = unsignedOf(file.root["buffers"][buffer], "byteLength");
        const std::uint64_t offset = unsignedOf(view, "byteOffset"), length = unsignedOf(view, "byteLength");
        if (offset > size || length > size - offset)
            file.fail(fmt::format("/bufferViews/{}/byteLength", v),
                      fmt::format("the view ends at byte {}, past the end of buffer {} ({} bytes)", offset + length,
                                  buffer, size));
        if (unsignedOf(view, "byteStride") > length)
            file.fail(fmt::format("/bufferViews/{}/byteStride", v),
                      fmt::format("{} is more than the view's {} bytes", unsignedOf(view, "byteStride"), length));
    }
}

// The accessors primitives use as vertex attributes.
std::set<std::uint64_t> vertexAccessors(const JsonFile& file)
{
    std::set<std::uint64_t> out;
    for (std::size_t m = 0; m < file.count("meshes"); ++m)
        for (const Json& primitive : file.root["meshes"][m]["primitives"])
            for (const auto& [semantic, accessor] : primitive["attributes"].items())
                out.insert(accessor.get<std::uint64_t>());
    return out;
}

// glTF 2.0, section 3.6.2.4: vertex attributes start on 4-byte boundaries, and a buffer view that more than one
// vertex attribute accessor reads says its byteStride.
void checkVertexAlignment(const JsonFile& file)
{
    std::map<std::uint64_t, std::uint64_t> readers; // buffer view -> accessors reading it as vertex attributes
    for (const std::uint64_t a : vertexAccessors(file)) {
        const Json& accessor = file.root["accessors"][a];
        if (!accessor.contains("bufferView"))
            continue;
        const std::uint64_t viewIndex = unsignedOf(accessor, "bufferView");
        const Json& view = file.root["bufferViews"][viewIndex];
        const auto element = std::uint64_t(componentSize(accessor["componentType"].get<std::int64_t>())) *
                             componentCount(accessor["type"].get<std::string>());
        const std::string at = fmt::format("/accessors/{}", a);
        if ((unsignedOf(view, "byteOffset") + unsignedOf(accessor, "byteOffset")) % 4 != 0)
            file.fail(at + "/byteOffset",
                      "a vertex attribute starts at a byte of its buffer that is not a multiple of 4");
        if (!view.contains("byteStride") && element % 4 != 0)
            file.fail(at, fmt::format("vertex attribute elements of {} bytes need a byteStride in buffer view {}",
                                      element, viewIndex));
        if (++readers[viewIndex] > 1 && !view.contains("byteStride"))
            file.fail(fmt::format("/bufferViews/{}", viewIndex),
                      "more than one vertex attribute accessor reads the view, which has no byteStride");
    }
}

void checkAccessorLayout(const JsonFile& file)
{
    for (std::size_t a = 0; a < file.count("accessors"); ++a) {
        const Json& accessor = file.root["accessors"][a];
        const std::string at = fmt::format("/accessors/{}", a);
        const std::uint64_t count = unsignedOf(accessor, "count");
        if (count > kMaxAccessorElements)
            file.fail(at + "/count", fmt::format("{} elements, over the limit of {}", count, kMaxAccessorElements));
        if (!accessor.contains("bufferView"))
            continue;
        const std::uint64_t viewIndex = unsignedOf(accessor, "bufferView");
        const Json& view = file.root["bufferViews"][viewIndex];
        const auto component = std::uint64_t(componentSize(accessor["componentType"].get<std::int64_t>()));
        const std::uint64_t element = component * componentCount(accessor["type"].get<std::string>());
        const std::uint64_t stride = unsignedOf(view, "byteStride", element);
        const std::uint64_t offset = unsignedOf(accessor, "byteOffset");
        if (stride < element)
            file.fail(fmt::format("/bufferViews/{}/byteStride", viewIndex),
                      fmt::format("{} is smaller than an element of accessor {} ({} bytes)", stride, a, element));
        if ((unsignedOf(view, "byteOffset") + offset) % component != 0)
            file.fail(at + "/byteOffset",
                      fmt::format("the accessor starts at byte {} of its buffer, not a multiple of its component "
                                  "size {}",
                                  unsignedOf(view, "byteOffset") + offset, component));
        const std::uint64_t end = offset + stride * (count - 1) + element;
        if (end > unsignedOf(view, "byteLength"))
            file.fail(at + "/count", fmt::format("{} elements need {} bytes of buffer view {}, which has {}", count,
                                                 end, viewIndex, unsignedOf(view, "byteLength")));
    }
}

} // namespace

void checkLayout(const JsonFile& file, const tinygltf::Model& model)
{
    checkBufferLayout(file, model);
    checkAccessorLayout(file);
    checkVertexAlignment(file);
}

} // namespace penumbra::gltf
