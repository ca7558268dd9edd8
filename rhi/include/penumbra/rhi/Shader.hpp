#pragma once

#include "penumbra/rhi/Format.hpp"
#include "penumbra/rhi/LiveObjects.hpp"
#include "penumbra/rhi/UniformLayout.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::rhi {

class PipelineCache;

enum class ShaderStage : std::uint8_t { Vertex, Fragment, Compute };

// GLSL 450 written once for both backends. `name` is what error messages cite
// (usually the file path). The RHI prepends Conventions::glslHeader() after #version.
// Binding model: one flat namespace of `layout(binding = N)` numbers per pipeline, shared
// by uniform blocks (std140), combined samplers, storage blocks (std430, `buffer`) and storage images
// (`image2D` with a format qualifier); no push constants, no descriptor sets. Vertex and fragment shaders read
// storage blocks only (`readonly`); compute shaders read and write both kinds of storage.
struct ShaderInclude {
    std::string name;
    std::string source;
};

// `#include "name"` lines resolve against `includes` (GL_GOOGLE_include_directive, enabled by
// the RHI); errors inside an included file cite that file's name and line.
struct ShaderSource {
    ShaderStage stage = ShaderStage::Vertex;
    std::string source;
    std::string name = "<inline>";
    std::vector<ShaderInclude> includes;
};

enum class BindingKind : std::uint8_t { UniformBuffer, SampledTexture, StorageBuffer, StorageTexture };

// One binding a shader declares, as reflection finds it: number, kind, name, size of a uniform or storage block.
struct ShaderBinding {
    std::uint32_t binding = 0;
    BindingKind kind = BindingKind::UniformBuffer;
    std::string name;
    // Block size in bytes: std140 for a uniform block, std430 for a storage block without its runtime array.
    std::uint32_t size = 0;
    // A block's members as reflection gives them (offsets and sizes; a runtime array's size is its element
    // stride); `name` is the block's.
    std::vector<UniformMember> members;
    // A storage block or image the shader may write (not declared `readonly`).
    bool writes = false;
    // A storage image's format qualifier (`layout(rgba8)`); the bound texture must have it.
    std::optional<Format> format;
};

// glslang's SPIR-V for one stage, with the bindings it declares.
struct CompiledShader {
    ShaderStage stage = ShaderStage::Vertex;
    std::string name;
    std::vector<std::uint32_t> spirv;
    std::vector<ShaderBinding> bindings;
    // A compute shader's `layout(local_size_x = ...)`, x, y, z; zero for other stages.
    std::array<std::uint32_t, 3> workgroupSize{};
    // Bytes of its `shared` variables, tightly packed (the driver may round up); zero for other stages.
    std::uint32_t sharedMemoryBytes = 0;
};

// A compiled shader stage of one device, for PipelineDesc.
class Shader : private LiveObject<ObjectKind::Shader> {
public:
    virtual ~Shader() = default;
    // The SPIR-V and reflection the shader was created from.
    virtual const CompiledShader& compiled() const = 0;
};

// Compiles GLSL 450 to SPIR-V with `preamble` inserted after #version. Throws
// ShaderCompileError carrying glslang's log ("ERROR: name:line: message").
CompiledShader compileShader(const ShaderSource& source, const std::string& preamble);
// The same, with SPIR-V kept in `disk` (null: none): a shader compiled by an earlier process is read back and
// reflected instead of compiled.
CompiledShader compileShader(const ShaderSource& source, const std::string& preamble, PipelineCache* disk);
// Empties the process's memo of compiled shaders, so that the next compileShader of any source reads the disk or
// runs glslang again (tests of the pipeline cache use it to act as a second process).
void forgetCompiledShaders();

} // namespace penumbra::rhi
