#pragma once

#include "penumbra/rhi/UniformLayout.hpp"
#include "penumbra/shaders/ShaderConstant.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

// A block shared by C++ and GLSL, declared once: the C++ struct that is uploaded, and beside it a ShaderStruct that
// lists its fields by name (PENUMBRA_SHADER_FIELD takes each field's GLSL type, array size, offset and size from the
// C++ member). From the list come the GLSL block text (uniformBlockGlsl, storageBlockGlsl, injected into the shaders
// as an include), the rhi::UniformLayout that pipeline creation compares with reflection (uniformLayout,
// storageLayout), and a compile-time check that the C++ offsets are the ones std140 (or std430) gives the GLSL
// (matchesLayout, in a static_assert). No shader writes a block body by hand (ctest format.shader-blocks).
// The model is Filament's UibGenerator (filament/src/details/UibGenerator.cpp): a block is a list of named fields.
namespace penumbra::shaders {

// The two GLSL buffer layouts (GLSL 4.50 spec, section 7.6.2.2 "Standard Uniform Block Layout"): std140 for uniform
// blocks; std430 for storage blocks, where arrays and structs are not rounded up to a vec4.
enum class BlockLayout : std::uint8_t { Std140, Std430 };

// A storage block's memory qualifier (GLSL 4.50, section 4.10): what the shader may do with it.
enum class BlockAccess : std::uint8_t { ReadWrite, ReadOnly, WriteOnly };

enum class FieldType : std::uint8_t { Float, Int, UInt, Vec2, Vec3, Vec4, IVec2, IVec4, UVec4, Mat4, Struct };

struct ShaderStruct;

// One named field: its GLSL type, array size (0: not an array) and the C++ member's offset and size.
struct ShaderField {
    std::string_view name;
    FieldType type = FieldType::Float;
    std::uint32_t count = 0;
    std::uint32_t offset = 0;
    std::uint32_t size = 0;
    const ShaderStruct* structure = nullptr; // the field's struct type where type is FieldType::Struct
    // The constant that names the array's length in GLSL (`uint bins[PENUMBRA_BINS]`), shared with the shader's code;
    // null: the length is written as a number.
    const ShaderConstant* length = nullptr;
    // A runtime-sized array (`float weights[]`), the last field of a storage block; `size` is one element's.
    bool runtime = false;
};

// A GLSL struct or block body: its name (the block name, or the struct type's), the C++ struct's size, its fields.
struct ShaderStruct {
    std::string_view name;
    std::uint32_t size = 0;
    std::span<const ShaderField> fields;
};

namespace detail {

template <class T>
struct FieldTypeOf;
template <>
struct FieldTypeOf<float> {
    static constexpr FieldType type = FieldType::Float;
};
template <>
struct FieldTypeOf<std::int32_t> {
    static constexpr FieldType type = FieldType::Int;
};
// An enum of int's size is a GLSL int: its values are generated into the shaders as #defines (the shadow filter,
// the cascade blend), so the C++ field keeps the one enum type instead of an int copy.
template <class T>
requires std::is_enum_v<T> && std::is_same_v < std::underlying_type_t<T>,
int > struct FieldTypeOf<T> {
    static constexpr FieldType type = FieldType::Int;
};
template <>
struct FieldTypeOf<std::uint32_t> {
    static constexpr FieldType type = FieldType::UInt;
};
template <>
struct FieldTypeOf<glm::vec2> {
    static constexpr FieldType type = FieldType::Vec2;
};
template <>
struct FieldTypeOf<glm::vec3> {
    static constexpr FieldType type = FieldType::Vec3;
};
template <>
struct FieldTypeOf<glm::vec4> {
    static constexpr FieldType type = FieldType::Vec4;
};
template <>
struct FieldTypeOf<glm::ivec2> {
    static constexpr FieldType type = FieldType::IVec2;
};
template <>
struct FieldTypeOf<glm::ivec4> {
    static constexpr FieldType type = FieldType::IVec4;
};
template <>
struct FieldTypeOf<glm::uvec4> {
    static constexpr FieldType type = FieldType::UVec4;
};
template <>
struct FieldTypeOf<glm::mat4> {
    static constexpr FieldType type = FieldType::Mat4;
};

template <class T>
struct ArrayOf {
    using Element = T;
    static constexpr std::uint32_t count = 0;
};
template <class T, std::size_t N>
struct ArrayOf<std::array<T, N>> {
    using Element = T;
    static constexpr std::uint32_t count = std::uint32_t(N);
};

constexpr std::uint32_t roundUp(std::uint32_t value, std::uint32_t alignment)
{
    return (value + alignment - 1) / alignment * alignment;
}

// `field` with its array length named by `length`; a length other than the C++ array's fails to compile (a throw
// in a constant expression).
constexpr ShaderField namedLength(ShaderField field, const ShaderConstant& length)
{
    if (field.count == 0 || std::int64_t(field.count) != length.value)
        throw std::logic_error("a shader field's named length differs from its C++ array's length");
    field.length = &length;
    return field;
}

} // namespace detail

// A field of C++ type Member (a scalar, glm vector or matrix, or a std::array of one), named as in GLSL.
template <class Member>
constexpr ShaderField shaderField(std::string_view name, std::size_t offset)
{
    using Array = detail::ArrayOf<Member>;
    return {name,
            detail::FieldTypeOf<typename Array::Element>::type,
            Array::count,
            std::uint32_t(offset),
            std::uint32_t(sizeof(Member)),
            nullptr};
}

// A field whose C++ type Member is a std::array whose length GLSL names by `length` (its value the array's).
template <class Member>
constexpr ShaderField shaderField(std::string_view name, std::size_t offset, const ShaderConstant& length)
{
    return detail::namedLength(shaderField<Member>(name, offset), length);
}

// A field whose C++ type Member is a struct (or a std::array of one) declared by `structure`.
template <class Member>
constexpr ShaderField shaderStructField(std::string_view name, std::size_t offset, const ShaderStruct& structure)
{
    return {name,
            FieldType::Struct,
            detail::ArrayOf<Member>::count,
            std::uint32_t(offset),
            std::uint32_t(sizeof(Member)),
            &structure};
}

template <class Member>
constexpr ShaderField shaderStructField(std::string_view name, std::size_t offset, const ShaderStruct& structure,
                                        const ShaderConstant& length)
{
    return detail::namedLength(shaderStructField<Member>(name, offset, structure), length);
}

// The runtime-sized array `Element name[]` that ends a storage block (GLSL 4.50, section 4.1.9), at `offset`, where
// the C++ code writes its first element (after the header whose fields come before it in the block).
template <class Element>
constexpr ShaderField runtimeArrayField(std::string_view name, std::size_t offset)
{
    ShaderField field = shaderField<Element>(name, offset);
    field.runtime = true;
    return field;
}

template <class Element>
constexpr ShaderField runtimeStructArrayField(std::string_view name, std::size_t offset, const ShaderStruct& structure)
{
    ShaderField field = shaderStructField<Element>(name, offset, structure);
    field.runtime = true;
    return field;
}

constexpr bool isArray(const ShaderField& field) { return field.count > 0 || field.runtime; }

// The GLSL base alignment and size of one element of `field` (GLSL 4.50, 7.6.2.2, rules 1 to 9).
constexpr std::uint32_t elementAlignment(const ShaderField& field, BlockLayout layout);
constexpr std::uint32_t elementSize(const ShaderField& field, BlockLayout layout);

// The size GLSL gives `structure` (rule 9: its members' extent rounded up to its alignment).
constexpr std::uint32_t structAlignment(const ShaderStruct& structure, BlockLayout layout)
{
    std::uint32_t alignment = layout == BlockLayout::Std140 ? 16 : 4;
    for (const ShaderField& field : structure.fields) {
        const std::uint32_t a = elementAlignment(field, layout);
        alignment = a > alignment ? a : alignment;
    }
    return alignment;
}

constexpr std::uint32_t structExtent(const ShaderStruct& structure, BlockLayout layout);

constexpr std::uint32_t elementAlignment(const ShaderField& field, BlockLayout layout)
{
    std::uint32_t alignment = 4;
    switch (field.type) {
    case FieldType::Float:
    case FieldType::Int:
    case FieldType::UInt:
        alignment = 4;
        break;
    case FieldType::Vec2:
    case FieldType::IVec2:
        alignment = 8;
        break;
    case FieldType::Vec3:
    case FieldType::Vec4:
    case FieldType::IVec4:
    case FieldType::UVec4:
    case FieldType::Mat4:
        alignment = 16;
        break;
    case FieldType::Struct:
        alignment = structAlignment(*field.structure, layout);
        break;
    }
    // Rule 4: in std140 an array's elements align to a vec4.
    return isArray(field) && layout == BlockLayout::Std140 && alignment < 16 ? 16 : alignment;
}

constexpr std::uint32_t elementSize(const ShaderField& field, BlockLayout layout)
{
    std::uint32_t size = 4;
    switch (field.type) {
    case FieldType::Float:
    case FieldType::Int:
    case FieldType::UInt:
        size = 4;
        break;
    case FieldType::Vec2:
    case FieldType::IVec2:
        size = 8;
        break;
    case FieldType::Vec3:
        size = 12;
        break;
    case FieldType::Vec4:
    case FieldType::IVec4:
    case FieldType::UVec4:
        size = 16;
        break;
    case FieldType::Mat4:
        size = 64;
        break;
    case FieldType::Struct:
        size = structExtent(*field.structure, layout);
        break;
    }
    // An array's stride is its element rounded up to the element's alignment (rules 4 and 10).
    return isArray(field) ? detail::roundUp(size, elementAlignment(field, layout)) : size;
}

// Where GLSL puts each field of `structure`, and the end of its last field.
constexpr std::uint32_t fieldsEnd(const ShaderStruct& structure, BlockLayout layout)
{
    std::uint32_t end = 0;
    for (const ShaderField& field : structure.fields)
        end = detail::roundUp(end, elementAlignment(field, layout)) +
              elementSize(field, layout) * (field.count > 0 ? field.count : 1);
    return end;
}

constexpr std::uint32_t structExtent(const ShaderStruct& structure, BlockLayout layout)
{
    return detail::roundUp(fieldsEnd(structure, layout), structAlignment(structure, layout));
}

// True where every field of `block` (and of its struct fields) sits at the offset and takes the size that `layout`
// gives it in GLSL, and the C++ struct ends where the block does (rounded up to its alignment at most): the C++
// struct can be uploaded as it is. A runtime array ends a std430 block, its C++ elements a GLSL stride apart, and
// the C++ struct of the fields before it ends at or before its first element.
constexpr bool matchesLayout(const ShaderStruct& block, BlockLayout layout, bool nested = false)
{
    std::uint32_t offset = 0;
    for (std::size_t i = 0; i < block.fields.size(); ++i) {
        const ShaderField& field = block.fields[i];
        const std::uint32_t start = detail::roundUp(offset, elementAlignment(field, layout));
        const std::uint32_t size = elementSize(field, layout) * (field.count > 0 ? field.count : 1);
        if (field.offset != start || field.size != size)
            return false;
        if (field.type == FieldType::Struct && !matchesLayout(*field.structure, layout, true))
            return false;
        if (field.runtime)
            return !nested && layout == BlockLayout::Std430 && i + 1 == block.fields.size() && block.size >= offset &&
                   block.size <= start;
        offset = start + size;
    }
    // A struct field's stride is its padded extent; a block's C++ struct may end anywhere up to its alignment.
    return nested ? block.size == structExtent(block, layout)
                  : block.size >= offset && block.size <= detail::roundUp(offset, structAlignment(block, layout));
}

// `struct Name { ... };` with the struct types it holds before it, each behind an #ifndef (so a shader may take it
// from several includes), for a shader include.
std::string structGlsl(const ShaderStruct& structure);

// `layout(std140, binding = N) uniform Name { ... } instance;`, preceded by the definitions of its struct types
// (each once per shader, behind an #ifndef), for a shader include.
std::string uniformBlockGlsl(const ShaderStruct& block, std::uint32_t binding, std::string_view instance);

// `layout(std430, binding = N) readonly buffer Name { ... } instance;` (the qualifier as `access` says; no instance
// name where `instance` is empty, so the members are the shader's globals), preceded by the definitions of its
// struct types and the constants that name its arrays' lengths.
std::string storageBlockGlsl(const ShaderStruct& block, std::uint32_t binding, std::string_view instance,
                             BlockAccess access);

// A record of RGBA32F texels in a data texture (read with texelFetch), declared once as blocks are: the C++ struct
// that is uploaded, 16 bytes a texel, and a ShaderStruct naming its fields (padding left out). True where every field
// is a float or float vector (not an array) lying within one texel, and the struct is whole texels.
constexpr bool fitsTexels(const ShaderStruct& record)
{
    if (record.size == 0 || record.size % 16 != 0)
        return false;
    for (const ShaderField& field : record.fields) {
        const bool floats = field.type == FieldType::Float || field.type == FieldType::Vec2 ||
                            field.type == FieldType::Vec3 || field.type == FieldType::Vec4;
        if (!floats || field.count != 0 || field.offset % 4 != 0 ||
            field.offset / 16 != (field.offset + field.size - 1) / 16 || field.offset + field.size > record.size)
            return false;
    }
    return true;
}

// Per field of `record` (fitsTexels), a GLSL accessor that fetches the field's texel through `fetch(int record, int
// texel)`, a function the shader defines before it, and returns the field's lanes. Named `prefix` and the field's
// name capitalized: for the field `color` in bytes 16 to 27, `vec3 localLightColor(int record) { return
// localLightTexel(record, 1).xyz; }`. Throws std::invalid_argument for a record that does not fit texels.
std::string texelRecordGlsl(const ShaderStruct& record, std::string_view fetch, std::string_view prefix);

// The block as PipelineDesc::uniformLayouts takes it: every field, and the fields of struct fields as "outer.inner"
// (the first element's where the struct field is an array), as rhi reflection lists them.
rhi::UniformLayout uniformLayout(const ShaderStruct& block);

// The same for a storage block (std430), as storageLayouts takes it: a runtime array's size is its stride, and the
// block's size ends where the runtime array begins.
rhi::UniformLayout storageLayout(const ShaderStruct& block);

} // namespace penumbra::shaders

// The ShaderField of `member` of `Struct`, by offsetof and sizeof (Struct must be standard-layout); the GLSL name is
// the C++ one. An array member may name its length by a ShaderConstant after it.
#define PENUMBRA_SHADER_FIELD(Struct, member, ...)                                                                     \
    ::penumbra::shaders::shaderField<decltype(Struct::member)>(#member,                                                \
                                                               offsetof(Struct, member) __VA_OPT__(, ) __VA_ARGS__)
// The same for a member whose type is a struct declared by the ShaderStruct `structure`.
#define PENUMBRA_SHADER_STRUCT_FIELD(Struct, member, structure, ...)                                                   \
    ::penumbra::shaders::shaderStructField<decltype(Struct::member)>(#member, offsetof(Struct, member),                \
                                                                     structure __VA_OPT__(, ) __VA_ARGS__)
