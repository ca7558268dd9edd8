#include "GltfAccessors.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <span>

#include <glm/geometric.hpp>

namespace penumbra::gltf {
namespace {

std::string typeName(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    case TINYGLTF_TYPE_MAT2:
        return "MAT2";
    case TINYGLTF_TYPE_MAT3:
        return "MAT3";
    case TINYGLTF_TYPE_MAT4:
        return "MAT4";
    }
    return fmt::format("type {}", type);
}

std::string componentName(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT:
        return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return "DOUBLE";
    }
    return fmt::format("component type {}", componentType);
}

// Where an accessor's elements are: `data` is null for an accessor without a buffer view, whose
// elements are all zero.
struct ElementView {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
};

ElementView viewOf(const Document& document, int index, std::string_view owner, std::string_view semantic,
                   int expectedType, std::span<const int> componentTypes)
{
    const tinygltf::Model& model = document.model();
    const tinygltf::Accessor& accessor = document.at(model.accessors, index, "accessor", owner);
    const std::string what = fmt::format("{}: accessor {} ({})", owner, index, semantic);
    if (accessor.sparse.isSparse)
        document.fail(fmt::format("{} is sparse, which is not supported", what));
    const bool componentOk =
        std::find(componentTypes.begin(), componentTypes.end(), accessor.componentType) != componentTypes.end();
    if (accessor.type != expectedType || !componentOk) {
        std::string expected;
        for (int c : componentTypes)
            expected += (expected.empty() ? "" : " or ") + componentName(c);
        document.fail(fmt::format("{} is {} of {}, expected {} of {}", what, typeName(accessor.type),
                                  componentName(accessor.componentType), typeName(expectedType), expected));
    }
    const auto componentSize = static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(accessor.componentType));
    const auto elementSize = componentSize * static_cast<std::size_t>(tinygltf::GetNumComponentsInType(expectedType));
    ElementView view{nullptr, elementSize, accessor.count, accessor.componentType};
    if (accessor.bufferView < 0 || accessor.count == 0)
        return view;

    const tinygltf::BufferView& bufferView = document.at(model.bufferViews, accessor.bufferView, "buffer view", what);
    const std::string viewName = fmt::format("buffer view {}", accessor.bufferView);
    const tinygltf::Buffer& buffer = document.at(model.buffers, bufferView.buffer, "buffer", viewName);
    if (bufferView.byteOffset > buffer.data.size() ||
        bufferView.byteLength > buffer.data.size() - bufferView.byteOffset)
        document.fail(fmt::format("{} ends at byte {}, past the end of buffer {} ({} bytes)", viewName,
                                  bufferView.byteOffset + bufferView.byteLength, bufferView.buffer,
                                  buffer.data.size()));
    if (bufferView.byteStride != 0) {
        if (bufferView.byteStride < elementSize)
            document.fail(fmt::format("{}: byteStride {} of {} is smaller than one {} of {} ({} bytes)", what,
                                      bufferView.byteStride, viewName, typeName(expectedType),
                                      componentName(accessor.componentType), elementSize));
        view.stride = bufferView.byteStride;
    }
    const std::size_t end = accessor.byteOffset + view.stride * (accessor.count - 1) + elementSize;
    if (end > bufferView.byteLength)
        document.fail(fmt::format("{}: {} elements need {} bytes of {}, which has {}", what, accessor.count, end,
                                  viewName, bufferView.byteLength));
    view.data = buffer.data.data() + bufferView.byteOffset + accessor.byteOffset;
    return view;
}

template <typename T>
T load(const unsigned char* at)
{
    T value;
    std::memcpy(&value, at, sizeof(T));
    return value;
}

// One component as a float; normalized integers map to [0, 1], or [-1, 1] for signed ones, as glTF 2.0 section
// 3.11 defines: c / (2^n - 1) unsigned, max(c / (2^(n-1) - 1), -1) signed.
float component(const unsigned char* at, int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return float(load<std::uint8_t>(at)) / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return float(load<std::uint16_t>(at)) / 65535.0f;
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return std::max(float(load<std::int8_t>(at)) / 127.0f, -1.0f);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return std::max(float(load<std::int16_t>(at)) / 32767.0f, -1.0f);
    default:
        return load<float>(at);
    }
}

// The normalized value of an integer component as component() reads it (before the clamp at -1).
double normalizedScale(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1.0 / 255.0;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 1.0 / 65535.0;
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return 1.0 / 127.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return 1.0 / 32767.0;
    default:
        return 1.0;
    }
}

// glTF 2.0, section 3.6.2.5: an accessor's min and max are the least and greatest value of each component.
void checkBounds(const Document& document, int index, const std::vector<std::vector<double>>& components, double scale)
{
    const tinygltf::Accessor& accessor = document.model().accessors[std::size_t(index)];
    const auto differs = [&](const std::vector<double>& declared, bool least) {
        for (std::size_t c = 0; c < declared.size() && c < components.size(); ++c) {
            if (components[c].empty())
                continue;
            const auto [lo, hi] = std::minmax_element(components[c].begin(), components[c].end());
            // Normalized values clamp at -1 as component() does; other scales are 1.
            const double actual = least ? *lo : *hi,
                         expected = scale < 1.0 ? std::max(declared[c] * scale, -1.0) : declared[c];
            if (std::abs(actual - expected) > 1e-6 * std::max(1.0, std::abs(actual)))
                return true;
        }
        return false;
    };
    if (differs(accessor.minValues, true) || differs(accessor.maxValues, false))
        document.deviations().add(kMinMaxMismatch, fmt::format("/accessors/{}", index));
}

template <int N>
void checkBounds(const Document& document, int index, const std::vector<glm::vec<N, float>>& values, int componentType)
{
    std::vector<std::vector<double>> components(N);
    for (const glm::vec<N, float>& value : values)
        for (int c = 0; c < N; ++c)
            components[std::size_t(c)].push_back(value[c]);
    checkBounds(document, index, components, normalizedScale(componentType));
}

template <int N>
std::vector<glm::vec<N, float>> readFloats(const Document& document, const ElementView& view, int index,
                                           std::string_view owner, std::string_view semantic)
{
    std::vector<glm::vec<N, float>> values(view.count, glm::vec<N, float>(0.0f));
    if (!view.data)
        return values;
    const auto componentSize = static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(view.componentType));
    for (std::size_t i = 0; i < view.count; ++i) {
        for (int c = 0; c < N; ++c) {
            values[i][c] = component(view.data + i * view.stride + std::size_t(c) * componentSize, view.componentType);
            if (!std::isfinite(values[i][c]))
                document.fail(fmt::format("{}: accessor {} ({}) element {} is not finite", owner, index, semantic, i));
        }
    }
    checkBounds(document, index, values, view.componentType);
    if constexpr (N >= 3)
        if (semantic == "NORMAL" || semantic == "TANGENT")
            for (std::size_t i = 0; i < view.count; ++i)
                if (std::abs(glm::length(glm::vec3(values[i])) - 1.0f) > float(kUnitLengthTolerance)) {
                    document.deviations().add(kNonUnit, fmt::format("/accessors/{}", index));
                    break;
                }
    if constexpr (N == 4)
        if (semantic == "TANGENT")
            for (std::size_t i = 0; i < view.count; ++i)
                if (values[i].w != 1.0f && values[i].w != -1.0f)
                    document.fail(fmt::format("{}: accessor {} (TANGENT) element {} has w {}, expected 1 or -1", owner,
                                              index, i, values[i].w));
    return values;
}

constexpr std::array<int, 1> kFloatOnly{TINYGLTF_COMPONENT_TYPE_FLOAT};
constexpr std::array<int, 3> kFloatOrSignedNormalized{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                                      TINYGLTF_COMPONENT_TYPE_SHORT};
constexpr std::array<int, 3> kFloatOrNormalized{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};

// VECn elements of one of `componentTypes`, as floats.
template <int N, std::size_t C>
std::vector<glm::vec<N, float>> readVectors(const Document& document, int accessor, std::string_view owner,
                                            std::string_view semantic, const std::array<int, C>& componentTypes)
{
    constexpr int type = N == 2 ? TINYGLTF_TYPE_VEC2 : N == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
    const ElementView view = viewOf(document, accessor, owner, semantic, type, componentTypes);
    return readFloats<N>(document, view, accessor, owner, semantic);
}

} // namespace

std::string describe(std::string_view kind, int index, const std::string& name)
{
    return name.empty() ? fmt::format("{} {}", kind, index) : fmt::format("{} {} ('{}')", kind, index, name);
}

std::vector<glm::vec3> readVec3(const Document& document, int accessor, std::string_view owner,
                                std::string_view semantic)
{
    return readVectors<3>(document, accessor, owner, semantic, kFloatOnly);
}

std::vector<glm::vec2> readTexCoords(const Document& document, int accessor, std::string_view owner,
                                     std::string_view semantic)
{
    return readVectors<2>(document, accessor, owner, semantic, kFloatOrNormalized);
}

std::vector<glm::vec4> readVec4(const Document& document, int accessor, std::string_view owner,
                                std::string_view semantic)
{
    return readVectors<4>(document, accessor, owner, semantic, kFloatOnly);
}

std::vector<glm::vec4> readRotations(const Document& document, int accessor, std::string_view owner,
                                     std::string_view semantic)
{
    return readVectors<4>(document, accessor, owner, semantic, kFloatOrSignedNormalized);
}

std::vector<glm::vec4> readColors(const Document& document, int accessor, std::string_view owner,
                                  std::string_view semantic)
{
    // glTF 2.0 section 3.7.2.1: COLOR_n is VEC3 or VEC4.
    if (document.at(document.model().accessors, accessor, "accessor", owner).type != TINYGLTF_TYPE_VEC3)
        return readVectors<4>(document, accessor, owner, semantic, kFloatOrNormalized);
    std::vector<glm::vec4> colors;
    for (const glm::vec3& color : readVectors<3>(document, accessor, owner, semantic, kFloatOrNormalized))
        colors.emplace_back(color, 1.0f);
    return colors;
}

std::vector<std::uint32_t> readIndices(const Document& document, int accessor, std::string_view owner)
{
    constexpr std::array<int, 3> indexTypes{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};
    const ElementView view = viewOf(document, accessor, owner, "indices", TINYGLTF_TYPE_SCALAR, indexTypes);
    std::vector<std::uint32_t> indices(view.count, 0u);
    if (!view.data)
        return indices;
    for (std::size_t i = 0; i < view.count; ++i) {
        const unsigned char* at = view.data + i * view.stride;
        switch (view.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            indices[i] = load<std::uint8_t>(at);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            indices[i] = load<std::uint16_t>(at);
            break;
        default:
            indices[i] = load<std::uint32_t>(at);
            break;
        }
    }
    // glTF 2.0, section 3.7.2.1: the largest value of the index type is the primitive restart value, never an index.
    const std::uint32_t restart = view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 0xffu
                                  : view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 0xffffu
                                                                                                 : 0xffffffffu;
    for (std::size_t i = 0; i < indices.size(); ++i)
        if (indices[i] == restart)
            document.fail(fmt::format("{}: accessor {} (indices) element {} is the primitive restart value {}", owner,
                                      accessor, i, restart));
    std::vector<std::vector<double>> components(1);
    components[0].assign(indices.begin(), indices.end());
    checkBounds(document, accessor, components, 1.0);
    return indices;
}

std::vector<float> readComponents(const Document& document, int accessor, std::string_view owner,
                                  std::string_view semantic, int type, std::span<const int> componentTypes)
{
    const ElementView view = viewOf(document, accessor, owner, semantic, type, componentTypes);
    const auto components = static_cast<std::size_t>(tinygltf::GetNumComponentsInType(type));
    std::vector<float> values(view.count * components, 0.0f);
    if (!view.data)
        return values;
    const bool normalized = document.model().accessors[std::size_t(accessor)].normalized;
    const auto componentSize = static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(view.componentType));
    std::vector<std::vector<double>> perComponent(components);
    for (std::size_t i = 0; i < view.count; ++i)
        for (std::size_t c = 0; c < components; ++c) {
            const unsigned char* at = view.data + i * view.stride + c * componentSize;
            float value = 0.0f;
            if (normalized || view.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
                value = component(at, view.componentType);
            else if (view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE)
                value = float(load<std::uint8_t>(at));
            else
                value = float(load<std::uint16_t>(at));
            if (!std::isfinite(value))
                document.fail(
                    fmt::format("{}: accessor {} ({}) element {} is not finite", owner, accessor, semantic, i));
            values[i * components + c] = value;
            perComponent[c].push_back(value);
        }
    checkBounds(document, accessor, perComponent, normalized ? normalizedScale(view.componentType) : 1.0);
    return values;
}

std::size_t accessorCount(const Document& document, int accessor, std::string_view owner)
{
    return document.at(document.model().accessors, accessor, "accessor", owner).count;
}

} // namespace penumbra::gltf
