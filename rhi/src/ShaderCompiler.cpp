#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/PipelineCache.hpp"
#include "penumbra/rhi/Shader.hpp"

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/build_info.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <algorithm>
#include <chrono>
#include <cstring>
#include <list>
#include <mutex>
#include <optional>
#include <spirv_cross/spirv_cross.hpp>
#include <unordered_map>

namespace penumbra::rhi {
namespace {

// glslang keeps process-wide tables; they are set up once and kept for the process's life.
void initializeGlslang()
{
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage glslangStage(ShaderStage stage)
{
    switch (stage) {
    case ShaderStage::Vertex:
        return EShLangVertex;
    case ShaderStage::Fragment:
        return EShLangFragment;
    case ShaderStage::Compute:
        break;
    }
    return EShLangCompute;
}

// The RHI format of a storage image's format qualifier (GLSL 4.60 section 4.4.7, "Format Layout Qualifiers").
std::optional<Format> storageFormat(spv::ImageFormat format)
{
    switch (format) {
    case spv::ImageFormatRgba8:
        return Format::RGBA8;
    case spv::ImageFormatRgba16f:
        return Format::RGBA16F;
    case spv::ImageFormatRgba32f:
        return Format::RGBA32F;
    case spv::ImageFormatR8:
        return Format::R8;
    case spv::ImageFormatRg8:
        return Format::RG8;
    case spv::ImageFormatR16f:
        return Format::R16F;
    case spv::ImageFormatRg16f:
        return Format::RG16F;
    case spv::ImageFormatR32f:
        return Format::R32F;
    default:
        return std::nullopt;
    }
}

// Bytes of a variable of `type`, tightly packed: scalars, vectors, matrices, arrays and structs of them.
std::uint64_t packedBytes(const spirv_cross::Compiler& compiler, const spirv_cross::SPIRType& type)
{
    std::uint64_t count = 1;
    for (std::size_t i = 0; i < type.array.size(); ++i)
        count *= type.array_size_literal[i] ? type.array[i] : compiler.get_constant(type.array[i]).scalar();
    if (type.basetype == spirv_cross::SPIRType::Struct) {
        std::uint64_t members = 0;
        for (const spirv_cross::TypeID member : type.member_types)
            members += packedBytes(compiler, compiler.get_type(member));
        return count * members;
    }
    return count * (type.width / 8) * type.vecsize * type.columns;
}

// The `shared` variables' bytes: every OpVariable in the Workgroup storage class (SPIR-V 1.3 sections 2.3 and
// 3.7; OpVariable is opcode 59 with the result type, result id and storage class as its first operands).
std::uint32_t sharedMemoryBytes(const spirv_cross::Compiler& compiler, const std::vector<std::uint32_t>& spirv)
{
    constexpr std::size_t headerWords = 5;
    std::uint64_t bytes = 0;
    for (std::size_t i = headerWords; i < spirv.size();) {
        const std::uint32_t words = spirv[i] >> 16;
        if ((spirv[i] & 0xffffu) == spv::OpVariable && words >= 4 && spirv[i + 3] == spv::StorageClassWorkgroup)
            bytes += packedBytes(compiler, compiler.get_type_from_variable(spirv[i + 2]));
        i += std::max<std::uint32_t>(words, 1);
    }
    return std::uint32_t(bytes);
}

// A block member's size; a runtime array (`T data[]`) gives its element stride, which the C++ element must match.
std::uint32_t memberSize(const spirv_cross::Compiler& compiler, const spirv_cross::SPIRType& block, std::uint32_t i)
{
    const spirv_cross::SPIRType& member = compiler.get_type(block.member_types[i]);
    if (!member.array.empty() && member.array_size_literal.back() && member.array.back() == 0)
        return compiler.type_struct_member_array_stride(block, i);
    return std::uint32_t(compiler.get_declared_struct_member_size(block, i));
}

// The members of `type` (a block or struct) at `base`, and those of its struct members as "outer.inner" (the first
// element's where the member is an array), so a layout check reaches every field.
void appendMembers(const spirv_cross::Compiler& compiler, const spirv_cross::SPIRType& type, const std::string& prefix,
                   std::uint32_t base, std::vector<UniformMember>& members)
{
    for (std::uint32_t i = 0; i < type.member_types.size(); ++i) {
        const std::string name = prefix + compiler.get_member_name(type.self, i);
        const std::uint32_t offset = base + compiler.type_struct_member_offset(type, i);
        members.push_back({name, offset, memberSize(compiler, type, i)});
        const spirv_cross::SPIRType& member = compiler.get_type(type.member_types[i]);
        if (member.basetype == spirv_cross::SPIRType::Struct)
            appendMembers(compiler, compiler.get_type(member.self), name + ".", offset, members);
    }
}

std::vector<ShaderBinding> reflectBindings(const spirv_cross::Compiler& compiler, const std::string& name)
{
    const spirv_cross::ShaderResources resources = compiler.get_shader_resources();
    if (!resources.push_constant_buffers.empty())
        throw ShaderCompileError(
            fmt::format("{}: push constants are not part of the binding model; use a uniform block", name));
    if (!resources.separate_images.empty() || !resources.separate_samplers.empty())
        throw ShaderCompileError(fmt::format("{}: only uniform blocks, combined samplers (sampler2D...), storage "
                                             "blocks and storage images are supported",
                                             name));

    std::vector<ShaderBinding> bindings;
    auto add = [&](const spirv_cross::Resource& r, BindingKind kind) {
        if (compiler.get_decoration(r.id, spv::DecorationDescriptorSet) != 0)
            throw ShaderCompileError(fmt::format("{}: '{}' uses a descriptor set other than 0", name, r.name));
        if (!compiler.has_decoration(r.id, spv::DecorationBinding))
            throw ShaderCompileError(fmt::format("{}: '{}' needs layout(binding = N)", name, r.name));
        ShaderBinding b{.binding = compiler.get_decoration(r.id, spv::DecorationBinding), .kind = kind, .name = r.name};
        if (kind == BindingKind::UniformBuffer || kind == BindingKind::StorageBuffer) {
            const spirv_cross::SPIRType& block = compiler.get_type(r.base_type_id);
            b.size = std::uint32_t(compiler.get_declared_struct_size(block));
            appendMembers(compiler, block, "", 0, b.members);
        }
        if (kind == BindingKind::StorageBuffer)
            b.writes = !compiler.get_buffer_block_flags(r.id).get(spv::DecorationNonWritable);
        if (kind == BindingKind::StorageTexture) {
            const spirv_cross::SPIRType& image = compiler.get_type(r.type_id);
            b.writes = !compiler.has_decoration(r.id, spv::DecorationNonWritable);
            b.format = storageFormat(image.image.format);
            if (!b.format)
                throw ShaderCompileError(fmt::format("{}: storage image '{}' needs a format qualifier of an RHI "
                                                     "format (rgba8, rgba16f, rgba32f, r8, rg8, r16f, rg16f, r32f)",
                                                     name, r.name));
            if (image.image.dim != spv::Dim2D || image.image.arrayed || image.image.ms)
                throw ShaderCompileError(fmt::format("{}: storage image '{}' must be an image2D", name, r.name));
        }
        bindings.push_back(b);
    };
    for (const spirv_cross::Resource& r : resources.uniform_buffers)
        add(r, BindingKind::UniformBuffer);
    for (const spirv_cross::Resource& r : resources.sampled_images)
        add(r, BindingKind::SampledTexture);
    for (const spirv_cross::Resource& r : resources.storage_buffers)
        add(r, BindingKind::StorageBuffer);
    for (const spirv_cross::Resource& r : resources.storage_images)
        add(r, BindingKind::StorageTexture);
    return bindings;
}

// Includes nest at most this deep. glslang has no limit of its own: a file that includes itself recursed until
// memory ran out (found by the shader fuzz target).
constexpr std::size_t kMaxIncludeDepth = 32;

// The bindings, workgroup size and shared memory of `spirv`, compiled from `source`.
CompiledShader reflect(const ShaderSource& source, std::vector<std::uint32_t> spirv)
{
    CompiledShader compiled{.stage = source.stage, .name = source.name, .spirv = std::move(spirv)};
    const spirv_cross::Compiler compiler(compiled.spirv);
    compiled.bindings = reflectBindings(compiler, source.name);
    if (source.stage == ShaderStage::Compute) {
        for (std::uint32_t axis = 0; axis < 3; ++axis)
            compiled.workgroupSize[axis] = compiler.get_execution_mode_argument(spv::ExecutionModeLocalSize, axis);
        compiled.sharedMemoryBytes = sharedMemoryBytes(compiler, compiled.spirv);
    }
    return compiled;
}

// Resolves `#include "name"` against the source's include list; unknown names fail with the list.
class IncludeList : public glslang::TShader::Includer {
public:
    explicit IncludeList(const std::vector<ShaderInclude>& includes) : includes_(includes) {}

    IncludeResult* includeLocal(const char* headerName, const char* includerName, size_t depth) override
    {
        return includeSystem(headerName, includerName, depth);
    }

    IncludeResult* includeSystem(const char* headerName, const char*, size_t depth) override
    {
        if (depth > kMaxIncludeDepth) {
            // A failed include is an empty name with the error message as its text (glslang's ShaderLang.h).
            error_ = fmt::format("\"{}\" nested deeper than {} includes (does an include include itself?)", headerName,
                                 kMaxIncludeDepth);
            return new IncludeResult("", error_.data(), error_.size(), nullptr);
        }
        for (const ShaderInclude& include : includes_)
            if (include.name == headerName)
                return new IncludeResult(include.name, include.source.data(), include.source.size(), nullptr);
        return nullptr;
    }

    void releaseInclude(IncludeResult* result) override { delete result; }

private:
    const std::vector<ShaderInclude>& includes_;
    std::string error_;
};

// Everything the SPIR-V depends on, as one string: the stage, the preamble, the name errors cite, every source.
std::string compileKey(const ShaderSource& source, const std::string& preamble)
{
    std::string key =
        fmt::format("{}\n{}\n{}\n{}\n{}", int(source.stage), preamble.size(), preamble, source.name, source.source);
    for (const ShaderInclude& include : source.includes)
        key += fmt::format("\n{}\n{}\n{}", include.name, include.source.size(), include.source);
    return key;
}

CompiledShader compileWithGlslang(const ShaderSource& source, const std::string& preamble)
{
    initializeGlslang();
    const EShLanguage stage = glslangStage(source.stage);
    glslang::TShader shader(stage);
    const char* text = source.source.c_str();
    const char* name = source.name.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &name, 1);
    const std::string fullPreamble = "#extension GL_GOOGLE_include_directive : require\n" + preamble;
    shader.setPreamble(fullPreamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    IncludeList includer(source.includes);
    if (!shader.parse(GetDefaultResources(), 450, ENoProfile, false, false, messages, includer))
        throw ShaderCompileError(fmt::format("GLSL compile failed:\n{}", shader.getInfoLog()));

    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        throw ShaderCompileError(fmt::format("GLSL link failed for {}:\n{}", source.name, program.getInfoLog()));

    std::vector<std::uint32_t> spirv;
    glslang::SpvOptions options;
    options.validate = true;
    glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &options);
    return reflect(source, std::move(spirv));
}

// What the pipeline cache's "spirv" entries were made by: glslang's version and the targets compileWithGlslang
// asks for. Another glslang writes other SPIR-V, so its entries are foreign.
std::string spirvIdentity()
{
    return fmt::format("glslang {}.{}.{}{} SPIR-V 1.3 Vulkan 1.1 GLSL 450", GLSLANG_VERSION_MAJOR,
                       GLSLANG_VERSION_MINOR, GLSLANG_VERSION_PATCH, GLSLANG_VERSION_FLAVOR);
}

// The SPIR-V stored for `key`, reflected; nullopt when there is none or it does not hold up.
std::optional<CompiledShader> loadSpirv(PipelineCache& disk, const ShaderSource& source, const std::string& key)
{
    const std::optional<std::string> payload = disk.load("spirv", spirvIdentity(), key);
    if (!payload)
        return std::nullopt;
    constexpr std::uint32_t kSpirvMagic = 0x07230203; // SPIR-V 1.6 specification, section 2.3 "Physical Layout"
    std::vector<std::uint32_t> spirv(payload->size() / sizeof(std::uint32_t));
    std::memcpy(spirv.data(), payload->data(), spirv.size() * sizeof(std::uint32_t));
    std::string why;
    if (payload->size() % sizeof(std::uint32_t) != 0 || spirv.empty() || spirv.front() != kSpirvMagic)
        why = "not a SPIR-V module";
    else
        try {
            return reflect(source, std::move(spirv));
        } catch (const std::exception& e) {
            why = fmt::format("SPIR-V that reflection refuses: {}", e.what());
        }
    disk.refuse("spirv", spirvIdentity(), key, why);
    return std::nullopt;
}

CompiledShader compileThroughDisk(const ShaderSource& source, const std::string& preamble, const std::string& key,
                                  PipelineCache* disk)
{
    if (!disk)
        return compileWithGlslang(source, preamble);
    if (std::optional<CompiledShader> stored = loadSpirv(*disk, source, key))
        return std::move(*stored);
    const auto start = std::chrono::steady_clock::now();
    CompiledShader compiled = compileWithGlslang(source, preamble);
    const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - start;
    disk->store("spirv", spirvIdentity(), key,
                std::string_view(reinterpret_cast<const char*>(compiled.spirv.data()),
                                 compiled.spirv.size() * sizeof(std::uint32_t)),
                spent.count());
    return compiled;
}

constexpr std::size_t kShaderMemoEntries = 512;
using Recency = std::list<std::string>;
struct MemoEntry {
    CompiledShader shader;
    Recency::iterator recency;
};
struct Memo {
    std::mutex mutex;
    std::unordered_map<std::string, MemoEntry> compiled;
    Recency recency; // most recently used first
};

Memo& memo()
{
    static Memo shared;
    return shared;
}

} // namespace

// Compilation is a pure function of its inputs, and glslang plus SPIR-V validation cost tens of milliseconds for the
// lit shader: every renderer of a process (tests, scene reloads, the soak) compiles the same sources, so each is
// compiled once per process. The memo keeps the most recently used kShaderMemoEntries (a renderer uses a few
// dozen; a program that generates shaders, or a fuzzer, must not grow without bound). Failures are not kept: they
// throw every time.
CompiledShader compileShader(const ShaderSource& source, const std::string& preamble)
{
    return compileShader(source, preamble, nullptr);
}

// With a pipeline cache, a miss of the memo looks on disk before it runs glslang.
CompiledShader compileShader(const ShaderSource& source, const std::string& preamble, PipelineCache* disk)
{
    auto& [mutex, compiled, recency] = memo();
    std::string key = compileKey(source, preamble);
    {
        const std::lock_guard lock(mutex);
        if (const auto found = compiled.find(key); found != compiled.end()) {
            recency.splice(recency.begin(), recency, found->second.recency);
            return found->second.shader;
        }
    }
    CompiledShader result = compileThroughDisk(source, preamble, key, disk);
    const std::lock_guard lock(mutex);
    if (const auto found = compiled.find(key); found != compiled.end())
        return found->second.shader; // another thread compiled it meanwhile
    if (compiled.size() == kShaderMemoEntries) {
        compiled.erase(recency.back());
        recency.pop_back();
    }
    recency.push_front(key);
    return compiled.emplace(std::move(key), MemoEntry{std::move(result), recency.begin()}).first->second.shader;
}

void forgetCompiledShaders()
{
    Memo& shared = memo();
    const std::lock_guard lock(shared.mutex);
    shared.compiled.clear();
    shared.recency.clear();
}

} // namespace penumbra::rhi
