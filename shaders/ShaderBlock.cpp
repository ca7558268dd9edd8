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
    case FieldType::Mat4:
        return "mat4";
    case FieldType::Struct:
        return field.structure->name;
    }
    return "float";
}

std::string fieldLines(const ShaderStruct& structure)
{
    std::string text;
    for (const ShaderField& field : structure.fields)
        text += field.count > 0 ? fmt::format("    {} {}[{}];\n", glslType(field), field.name, field.count)
                                : fmt::format("    {} {};\n", glslType(field), field.name);
    return text;
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

void appendMembers(const ShaderStruct& structure, const std::string& prefix, std::uint32_t base,
                   std::vector<rhi::UniformMember>& members)
{
    for (const ShaderField& field : structure.fields) {
        const std::string name = prefix + std::string(field.name);
        // Reflection sizes a struct that is not an array by its last member's end, without the padding that rounds
        // it up to its alignment (matchesLayout checks the C++ struct's size against the padded one).
        const bool lone = field.type == FieldType::Struct && field.count == 0;
        members.push_back(
            {name, base + field.offset, lone ? fieldsEnd(*field.structure, BlockLayout::Std140) : field.size});
        if (field.type == FieldType::Struct)
            appendMembers(*field.structure, name + ".", base + field.offset, members);
    }
}

} // namespace

std::string structGlsl(const ShaderStruct& structure)
{
    std::string text;
    appendStructTypes(structure, text);
    text += fmt::format("#ifndef PENUMBRA_STRUCT_{0}\n#define PENUMBRA_STRUCT_{0}\nstruct {0} {{\n{1}}};\n#endif\n",
                        structure.name, fieldLines(structure));
    return text;
}

std::string uniformBlockGlsl(const ShaderStruct& block, std::uint32_t binding, std::string_view instance)
{
    std::string text;
    appendStructTypes(block, text);
    text += fmt::format("layout(std140, binding = {}) uniform {} {{\n{}}} {};\n", binding, block.name,
                        fieldLines(block), instance);
    return text;
}

std::string readonlyArrayBlockGlsl(const ShaderStruct& element, std::string_view block, std::uint32_t binding,
                                   std::string_view member, std::string_view instance)
{
    return structGlsl(element) +
           fmt::format("layout(std430, binding = {}) readonly buffer {} {{\n    {} {}[];\n}} {};\n", binding, block,
                       element.name, member, instance);
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

rhi::UniformLayout uniformLayout(const ShaderStruct& block)
{
    rhi::UniformLayout layout{std::string(block.name), 0, {}};
    appendMembers(block, "", 0, layout.members);
    // Reflection's block size is where its last member ends, so a trailing struct's padding is not in it.
    for (const ShaderField& field : block.fields) {
        const rhi::UniformMember& member =
            *std::find_if(layout.members.begin(), layout.members.end(),
                          [&](const rhi::UniformMember& m) { return m.name == field.name; });
        layout.size = std::max(layout.size, member.offset + member.size);
    }
    return layout;
}

} // namespace penumbra::shaders
