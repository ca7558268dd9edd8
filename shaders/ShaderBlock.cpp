#include "penumbra/shaders/ShaderBlock.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <fmt/format.h>

namespace penumbra::shaders {
namespace {

std::string_view glslType(const ShaderField& field)
{
    switch (field.type) {
    case FieldType::Float:
        return "float";
    case FieldType::Int:
        return "int";
    case FieldType::UInt:
        return "uint";
    case FieldType::Vec2:
        return "vec2";
    case FieldType::Vec3:
        return "vec3";
    case FieldType::Vec4:
        return "vec4";
    case FieldType::IVec2:
        return "ivec2";
    case FieldType::IVec4:
        return "ivec4";
    case FieldType::UVec4:
        return "uvec4";
    case FieldType::Mat4:
        return "mat4";
    case FieldType::Struct:
        return field.structure->name;
    }
    return "float";
}

std::string arraySuffix(const ShaderField& field)
{
    if (field.runtime)
        return "[]";
    if (field.length)
        return fmt::format("[PENUMBRA_{}]", field.length->name);
    return field.count > 0 ? fmt::format("[{}]", field.count) : "";
}

std::string fieldLines(const ShaderStruct& structure)
{
    std::string text;
    for (const ShaderField& field : structure.fields)
        text += fmt::format("    {} {}{};\n", glslType(field), field.name, arraySuffix(field));
    return text;
}

// The constants that name the arrays' lengths of `structure` and its struct types, each defined once per shader:
// where the shader has it already (from another block, or shaders::load's constants.glsl), it must have this value.
void appendLengths(const ShaderStruct& structure, std::string& text)
{
    for (const ShaderField& field : structure.fields) {
        if (field.type == FieldType::Struct)
            appendLengths(*field.structure, text);
        if (field.length)
            text += fmt::format("#ifndef PENUMBRA_{0}\n#define PENUMBRA_{0} {1}\n#elif PENUMBRA_{0} != {1}\n"
                                "#error PENUMBRA_{0} is not {1}, the length of {2}.{3}\n#endif\n",
                                field.length->name, field.length->value, structure.name, field.name);
    }
}

// Struct types before the structs that hold them; each behind a guard, as two blocks of one shader may share one.
void appendStructTypes(const ShaderStruct& structure, std::string& text)
{
    for (const ShaderField& field : structure.fields)
        if (field.type == FieldType::Struct) {
            appendStructTypes(*field.structure, text);
            text += fmt::format("#ifndef PENUMBRA_STRUCT_{0}\n#define PENUMBRA_STRUCT_{0}\nstruct {0} {{\n{1}}};\n"
                                "#endif\n",
                                field.structure->name, fieldLines(*field.structure));
        }
}

void appendMembers(const ShaderStruct& structure, BlockLayout layout, const std::string& prefix, std::uint32_t base,
                   std::vector<rhi::UniformMember>& members)
{
    for (const ShaderField& field : structure.fields) {
        const std::string name = prefix + std::string(field.name);
        // Reflection sizes a struct that is not an array by its last member's end, without the padding that rounds
        // it up to its alignment (matchesLayout checks the C++ struct's size against the padded one).
        const bool lone = field.type == FieldType::Struct && !isArray(field);
        members.push_back({name, base + field.offset, lone ? fieldsEnd(*field.structure, layout) : field.size});
        if (field.type == FieldType::Struct)
            appendMembers(*field.structure, layout, name + ".", base + field.offset, members);
    }
}

rhi::UniformLayout blockLayout(const ShaderStruct& block, BlockLayout layout)
{
    rhi::UniformLayout result{std::string(block.name), 0, {}};
    appendMembers(block, layout, "", 0, result.members);
    // Reflection's block size is where its last member ends, so a trailing struct's padding is not in it; a runtime
    // array adds nothing to it.
    for (const ShaderField& field : block.fields) {
        const rhi::UniformMember& member =
            *std::find_if(result.members.begin(), result.members.end(),
                          [&](const rhi::UniformMember& m) { return m.name == field.name; });
        result.size = std::max(result.size, member.offset + (field.runtime ? 0 : member.size));
    }
    return result;
}

constexpr std::string_view accessQualifier(BlockAccess access)
{
    switch (access) {
    case BlockAccess::ReadOnly:
        return "readonly ";
    case BlockAccess::WriteOnly:
        return "writeonly ";
    case BlockAccess::ReadWrite:
        break;
    }
    return "";
}

} // namespace

std::string structGlsl(const ShaderStruct& structure)
{
    std::string text;
    appendLengths(structure, text);
    appendStructTypes(structure, text);
    text += fmt::format("#ifndef PENUMBRA_STRUCT_{0}\n#define PENUMBRA_STRUCT_{0}\nstruct {0} {{\n{1}}};\n#endif\n",
                        structure.name, fieldLines(structure));
    return text;
}

std::string uniformBlockGlsl(const ShaderStruct& block, std::uint32_t binding, std::string_view instance)
{
    std::string text;
    appendLengths(block, text);
    appendStructTypes(block, text);
    text += fmt::format("layout(std140, binding = {}) uniform {} {{\n{}}} {};\n", binding, block.name,
                        fieldLines(block), instance);
    return text;
}

std::string storageBlockGlsl(const ShaderStruct& block, std::uint32_t binding, std::string_view instance,
                             BlockAccess access)
{
    std::string text;
    appendLengths(block, text);
    appendStructTypes(block, text);
    text += fmt::format("layout(std430, binding = {}) {}buffer {} {{\n{}}}{}{};\n", binding, accessQualifier(access),
                        block.name, fieldLines(block), instance.empty() ? "" : " ", instance);
    return text;
}

std::string texelRecordGlsl(const ShaderStruct& record, std::string_view fetch, std::string_view prefix)
{
    if (!fitsTexels(record))
        throw std::invalid_argument(fmt::format("texel record '{}': every field must be a float or float vector within "
                                                "one 16-byte texel, and the record whole texels ({} bytes)",
                                                record.name, record.size));
    std::string text =
        fmt::format("// Generated from the texel record {} ({} texels).\n", record.name, record.size / 16);
    for (const ShaderField& field : record.fields) {
        std::string name(field.name);
        name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
        const std::string_view lanes = std::string_view("xyzw").substr(field.offset % 16 / 4, field.size / 4);
        text += fmt::format("{} {}{}(int record) {{ return {}(record, {}).{}; }}\n", glslType(field), prefix, name,
                            fetch, field.offset / 16, lanes);
    }
    return text;
}

rhi::UniformLayout uniformLayout(const ShaderStruct& block) { return blockLayout(block, BlockLayout::Std140); }

rhi::UniformLayout storageLayout(const ShaderStruct& block) { return blockLayout(block, BlockLayout::Std430); }

} // namespace penumbra::shaders
