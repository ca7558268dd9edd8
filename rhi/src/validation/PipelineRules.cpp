// Pipeline rules: shaders, formats, vertex layout, features, and the C++ uniform layouts against reflection.

#include "Rules.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <fmt/format.h>

namespace penumbra::rhi {
namespace {

// GL 4.5 guarantees at least 8 draw buffers (Table 23.69, MAX_DRAW_BUFFERS); so do lavapipe's and every
// desktop Vulkan driver's maxColorAttachments.
constexpr std::size_t maxColorTargets = 8;

const UniformMember* findMember(const UniformLayout& layout, const std::string& name)
{
    auto found = std::find_if(layout.members.begin(), layout.members.end(),
                              [&](const UniformMember& m) { return m.name == name; });
    return found == layout.members.end() ? nullptr : &*found;
}

std::string_view blockName(BindingKind kind)
{
    return kind == BindingKind::UniformBuffer ? "uniform block" : "storage block";
}

// One reflected block against its C++ description; `shader` names the file that declares it. Uniform blocks are
// std140, storage blocks std430 (GLSL 4.60 section 4.4.5); the offsets reflection gives are the layout's either way.
void compareBlock(const std::string& pipeline, const UniformLayout& layout, const ShaderBinding& block,
                  const std::string& shader)
{
    const std::string_view kind = blockName(block.kind);
    for (const UniformMember& glsl : block.members) {
        const UniformMember* cpp = findMember(layout, glsl.name);
        if (!cpp)
            throw Error(fmt::format("pipeline '{}': {} '{}' member '{}' (offset {} in {}) is missing "
                                    "from the C++ layout",
                                    pipeline, kind, block.name, glsl.name, glsl.offset, shader));
        if (cpp->offset != glsl.offset)
            throw Error(fmt::format("pipeline '{}': {} '{}' member '{}' is at offset {} in {} but at "
                                    "offset {} in C++",
                                    pipeline, kind, block.name, glsl.name, glsl.offset, shader, cpp->offset));
        if (cpp->size != glsl.size)
            throw Error(fmt::format("pipeline '{}': {} '{}' member '{}' takes {} bytes in {} but {} in C++", pipeline,
                                    kind, block.name, glsl.name, glsl.size, shader, cpp->size));
    }
    for (const UniformMember& cpp : layout.members)
        if (std::none_of(block.members.begin(), block.members.end(),
                         [&](const UniformMember& m) { return m.name == cpp.name; }))
            throw Error(fmt::format("pipeline '{}': {} '{}' has no member '{}' in {}, but the C++ layout "
                                    "has",
                                    pipeline, kind, block.name, cpp.name, shader));
    if (layout.size != block.size)
        throw Error(fmt::format("pipeline '{}': {} '{}' is {} bytes in {} but {} bytes in C++", pipeline, kind,
                                block.name, block.size, shader, layout.size));
}

// Each layout against the block of its name and kind in `shaders`.
void checkLayouts(const std::string& pipeline, const std::vector<UniformLayout>& layouts, BindingKind kind,
                  std::span<const Shader* const> shaders)
{
    for (const UniformLayout& layout : layouts) {
        bool declared = false;
        for (const Shader* shader : shaders)
            for (const ShaderBinding& b : shader->compiled().bindings)
                if (b.kind == kind && b.name == layout.block) {
                    compareBlock(pipeline, layout, b, shader->compiled().name);
                    declared = true;
                }
        if (!declared) {
            std::string names;
            for (const Shader* shader : shaders)
                names += (names.empty() ? "" : " or ") + shader->compiled().name;
            throw Error(fmt::format("pipeline '{}': the C++ layout of {} '{}' matches no block of {}", pipeline,
                                    blockName(kind), layout.block, names));
        }
    }
}

// Vertex and fragment shaders read storage blocks and use no storage images, so that graphics never writes what the
// hazard tracker must order (and Vulkan's vertexPipelineStoresAndAtomics is not needed).
void checkGraphicsStorage(const PipelineDesc& desc)
{
    for (const Shader* shader : {desc.vertex, desc.fragment})
        for (const ShaderBinding& b : shader->compiled().bindings) {
            if (b.kind == BindingKind::StorageTexture)
                throw Error(fmt::format("pipeline '{}': storage image '{}' in {}: vertex and fragment shaders use no "
                                        "storage images",
                                        desc.debugName, b.name, shader->compiled().name));
            if (b.kind == BindingKind::StorageBuffer && b.writes)
                throw Error(fmt::format("pipeline '{}': storage block '{}' in {} is not readonly: vertex and fragment "
                                        "shaders only read storage blocks",
                                        desc.debugName, b.name, shader->compiled().name));
        }
}

} // namespace

void checkInstanceRange(std::string_view what, const PipelineDesc& desc, std::span<const std::uint64_t> boundBytes,
                        std::uint32_t instanceCount, std::uint32_t firstInstance)
{
    if (instanceCount == 0)
        return;
    const VertexLayout& layout = desc.vertexLayout;
    for (std::uint32_t slot = 0; slot < layout.buffers.size(); ++slot) {
        if (!layout.buffers[slot].perInstance)
            continue;
        std::uint64_t attributeEnd = 0;
        for (const VertexAttribute& a : layout.attributes)
            if (a.buffer == slot)
                attributeEnd = std::max<std::uint64_t>(attributeEnd, a.offset + vertexFormatSize(a.format));
        const std::uint64_t needed =
            std::uint64_t(firstInstance + instanceCount - 1) * layout.buffers[slot].stride + attributeEnd;
        if (attributeEnd > 0 && needed > boundBytes[slot])
            throw Error(fmt::format("{}: pipeline '{}' reads instances {} to {} from vertex buffer slot {} ({} bytes), "
                                    "but {} bytes are bound there",
                                    what, desc.debugName, firstInstance, firstInstance + instanceCount - 1, slot,
                                    needed, boundBytes[slot]));
    }
}

void checkPipeline(const Capabilities& caps, const PipelineDesc& desc)
{
    if (!desc.vertex || !desc.fragment)
        throw Error(fmt::format("pipeline '{}' needs a vertex and a fragment shader", desc.debugName));
    if (desc.vertex->compiled().stage != ShaderStage::Vertex ||
        desc.fragment->compiled().stage != ShaderStage::Fragment)
        throw Error(fmt::format("pipeline '{}': shader stages are swapped", desc.debugName));
    if (desc.depthFormat && !isDepthFormat(*desc.depthFormat))
        throw Error(fmt::format("pipeline '{}': depthFormat {} is not a depth format", desc.debugName,
                                formatName(*desc.depthFormat)));
    for (const ColorTarget& c : desc.colorTargets)
        if (isDepthFormat(c.format))
            throw Error(fmt::format("pipeline '{}': colour target format {} is a depth format", desc.debugName,
                                    formatName(c.format)));
    if (desc.colorTargets.size() > maxColorTargets)
        throw Error(fmt::format("pipeline '{}': {} colour targets, at most {}", desc.debugName,
                                desc.colorTargets.size(), maxColorTargets));
    for (const VertexAttribute& a : desc.vertexLayout.attributes)
        if (a.buffer >= desc.vertexLayout.buffers.size())
            throw Error(fmt::format("pipeline '{}': attribute at location {} reads vertex buffer slot {}, but the "
                                    "layout describes {} buffer(s)",
                                    desc.debugName, a.location, a.buffer, desc.vertexLayout.buffers.size()));
    if (desc.samples != 1 && desc.samples != 2 && desc.samples != 4 && desc.samples != 8)
        throw Error(fmt::format("pipeline '{}': samples {} is not 1, 2, 4 or 8", desc.debugName, desc.samples));
    std::vector<Format> targets;
    for (const ColorTarget& c : desc.colorTargets)
        targets.push_back(c.format);
    if (desc.depthFormat)
        targets.push_back(*desc.depthFormat);
    if ((caps.sampleCounts(targets) & desc.samples) == 0) {
        std::string formats;
        for (Format f : targets)
            formats += (formats.empty() ? "" : ", ") + std::string(formatName(f));
        throw UnsupportedError(fmt::format("pipeline '{}': {} offers {} samples for {}, not {}", desc.debugName,
                                           caps.device, sampleCountList(caps.sampleCounts(targets)), formats,
                                           desc.samples));
    }
    if (desc.depth.clamp && !caps.depthClamp)
        throw UnsupportedError(
            fmt::format("pipeline '{}': depth clamp is not supported by {}", desc.debugName, caps.device));
    if (desc.depth.bias.clamp != 0.0f && !caps.depthBiasClamp)
        throw UnsupportedError(
            fmt::format("pipeline '{}': depth bias clamp is not supported by {}", desc.debugName, caps.device));
    checkPipelineBindingSetLayouts(desc.debugName, desc.bindingSetLayouts, pipelineBindings(desc));
    checkGraphicsStorage(desc);
    checkUniformLayouts(desc);
}

void checkUniformLayouts(const PipelineDesc& desc)
{
    const std::array<const Shader*, 2> shaders{desc.vertex, desc.fragment};
    checkLayouts(desc.debugName, desc.uniformLayouts, BindingKind::UniformBuffer, shaders);
    checkLayouts(desc.debugName, desc.storageLayouts, BindingKind::StorageBuffer, shaders);
}

void checkWorkgroup(const Capabilities& caps, const CompiledShader& shader)
{
    const std::array<std::uint32_t, 3>& size = shader.workgroupSize;
    const std::uint64_t invocations = std::uint64_t(size[0]) * size[1] * size[2];
    for (std::size_t axis = 0; axis < 3; ++axis)
        if (size[axis] > caps.maxWorkgroupSize[axis])
            throw Error(fmt::format("{}: local_size_{} = {} exceeds Capabilities::maxWorkgroupSize ({})", shader.name,
                                    "xyz"[axis], size[axis], caps.maxWorkgroupSize[axis]));
    if (invocations > caps.maxWorkgroupInvocations)
        throw Error(fmt::format("{}: {}x{}x{} = {} invocations per workgroup exceed "
                                "Capabilities::maxWorkgroupInvocations ({})",
                                shader.name, size[0], size[1], size[2], invocations, caps.maxWorkgroupInvocations));
    if (shader.sharedMemoryBytes > caps.maxComputeSharedMemory)
        throw Error(fmt::format("{}: {} bytes of shared variables exceed Capabilities::maxComputeSharedMemory ({})",
                                shader.name, shader.sharedMemoryBytes, caps.maxComputeSharedMemory));
}

void checkComputePipeline(const ComputePipelineDesc& desc)
{
    if (!desc.compute)
        throw Error(fmt::format("compute pipeline '{}' needs a compute shader", desc.debugName));
    const CompiledShader& shader = desc.compute->compiled();
    if (shader.stage != ShaderStage::Compute)
        throw Error(
            fmt::format("compute pipeline '{}': shader {} is not a compute shader", desc.debugName, shader.name));
    const std::array<const Shader*, 1> shaders{desc.compute};
    checkLayouts(desc.debugName, desc.uniformLayouts, BindingKind::UniformBuffer, shaders);
    checkLayouts(desc.debugName, desc.storageLayouts, BindingKind::StorageBuffer, shaders);
    checkPipelineBindingSetLayouts(desc.debugName, desc.bindingSetLayouts, shader.bindings);
}

} // namespace penumbra::rhi
