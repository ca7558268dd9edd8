#pragma once

#include "penumbra/rhi/LiveObjects.hpp"
#include "penumbra/rhi/UniformLayout.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::rhi {

enum class ShaderStage : std::uint8_t { Vertex, Fragment };

// GLSL 450 written once for both backends. `name` is what error messages cite
// (usually the file path). The RHI prepends Conventions::glslHeader() after #version.
// Binding model: one flat namespace of `layout(binding = N)` numbers per pipeline, shared
// by uniform blocks (std140) and combined samplers; no push constants, no descriptor sets.
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

enum class BindingKind : std::uint8_t { UniformBuffer, SampledTexture };

// One binding a shader declares, as reflection finds it: number, kind, name, size of a uniform block.
struct ShaderBinding {
    std::uint32_t binding = 0;
    BindingKind kind = BindingKind::UniformBuffer;
    std::string name;
    std::uint32_t size = 0; // uniform block size in bytes (std140)
    // A uniform block's members as reflection gives them (std140 offsets and sizes); `name` is the block's.
    std::vector<UniformMember> members;
};

// glslang's SPIR-V for one stage, with the bindings it declares.
struct CompiledShader {
    ShaderStage stage = ShaderStage::Vertex;
    std::string name;
    std::vector<std::uint32_t> spirv;
    std::vector<ShaderBinding> bindings;
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

} // namespace penumbra::rhi
