#include "VulkanSpirvSets.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>
#include <unordered_map>

namespace penumbra::vulkan {
namespace {

// SPIR-V 1.6 specification, section 2.3 "Physical Layout of a SPIR-V Module and Instruction" (a 5-word header, then
// instructions whose first word holds the word count in its high half and the opcode in its low half), the Decoration
// table (Binding 33, DescriptorSet 34) and OpDecorate (opcode 71: target id, decoration, literal).
constexpr std::size_t kHeaderWords = 5;
constexpr std::uint32_t kOpDecorate = 71;
constexpr std::uint32_t kDecorationBinding = 33;
constexpr std::uint32_t kDecorationDescriptorSet = 34;

// Calls visit(first word index, word count, opcode) for each instruction.
template <typename Visit>
void forEachInstruction(const std::vector<std::uint32_t>& words, const std::string& name, Visit visit)
{
    for (std::size_t i = kHeaderWords; i < words.size();) {
        const std::uint32_t count = words[i] >> 16;
        if (count == 0 || i + count > words.size())
            throw rhi::Error(fmt::format("{}: malformed SPIR-V at word {}", name, i));
        visit(i, count, words[i] & 0xffffu);
        i += count;
    }
}

} // namespace

std::vector<std::uint32_t> assignDescriptorSets(const rhi::CompiledShader& shader, const DescriptorLayout& layout)
{
    std::vector<std::uint32_t> words = shader.spirv;
    std::unordered_map<std::uint32_t, std::uint32_t> bindingOf; // by variable id
    forEachInstruction(words, shader.name, [&](std::size_t i, std::uint32_t count, std::uint32_t op) {
        if (op == kOpDecorate && count >= 4 && words[i + 2] == kDecorationBinding)
            bindingOf[words[i + 1]] = words[i + 3];
    });
    std::size_t assigned = 0;
    forEachInstruction(words, shader.name, [&](std::size_t i, std::uint32_t count, std::uint32_t op) {
        if (op != kOpDecorate || count < 4 || words[i + 2] != kDecorationDescriptorSet)
            return;
        const auto found = bindingOf.find(words[i + 1]);
        if (found == bindingOf.end())
            return;
        const std::uint32_t set = layout.setOf(found->second);
        if (set == DescriptorLayout::kUndeclared)
            throw rhi::Error(
                fmt::format("{}: binding {} is not among the pipeline's bindings", shader.name, found->second));
        words[i + 3] = set;
        ++assigned;
    });
    if (assigned != bindingOf.size())
        throw rhi::Error(fmt::format("{}: {} resources have a binding but no descriptor set decoration", shader.name,
                                     bindingOf.size() - assigned));
    return words;
}

} // namespace penumbra::vulkan
