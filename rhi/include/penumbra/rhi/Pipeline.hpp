#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Flags.hpp"
#include "penumbra/rhi/Format.hpp"
#include "penumbra/rhi/LiveObjects.hpp"
#include "penumbra/rhi/Shader.hpp"
#include "penumbra/rhi/UniformLayout.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::rhi {

class BindingSetLayout;

enum class VertexFormat : std::uint8_t { Float, Float2, Float3, Float4, UByte4Norm };

// Bytes of one attribute of the format.
constexpr std::uint32_t vertexFormatSize(VertexFormat format)
{
    switch (format) {
    case VertexFormat::Float:
    case VertexFormat::UByte4Norm:
        return 4;
    case VertexFormat::Float2:
        return 8;
    case VertexFormat::Float3:
        return 12;
    case VertexFormat::Float4:
        break;
    }
    return 16;
}

// One vertex attribute: its shader location, format and byte offset in its buffer's vertex.
struct VertexAttribute {
    std::uint32_t location = 0;
    VertexFormat format = VertexFormat::Float3;
    std::uint32_t offset = 0;
    std::uint32_t buffer = 0; // vertex buffer slot
};

// One vertex buffer slot: its stride and whether it advances per vertex or per instance.
struct VertexBufferLayout {
    std::uint32_t stride = 0;
    bool perInstance = false;
};

// The vertex buffers a pipeline reads and their attributes.
struct VertexLayout {
    std::vector<VertexBufferLayout> buffers;
    std::vector<VertexAttribute> attributes;
};

enum class PrimitiveTopology : std::uint8_t { TriangleList, TriangleStrip, LineList, PointList };

// Front faces are counter-clockwise in canonical NDC (y up) on every backend.
enum class CullMode : std::uint8_t { None, Back, Front };

// Constant and slope-scale depth bias, positive away from the viewer (the conventions flip the
// sign for reversed-Z). Units are the APIs' own: `constant` in minimum resolvable depth
// differences, `slope` times the polygon's max depth slope; `clamp` bounds the magnitude (0: none).
struct DepthBias {
    float constant = 0.0f;
    float slope = 0.0f;
    float clamp = 0.0f;
};

// Depth test, write, bias and clamp of a pipeline.
struct DepthState {
    bool test = false;
    bool write = false;
    DepthTest compare = DepthTest::Nearer;
    DepthBias bias;
    // Depth clamp instead of near/far clipping: the pancaking of shadow casters.
    bool clamp = false;
};

enum class ColorMask : std::uint8_t { None = 0, R = 1, G = 2, B = 4, A = 8, All = 15 };
constexpr bool enableFlags(ColorMask) { return true; }

enum class BlendFactor : std::uint8_t {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstColor,
    OneMinusDstColor,
    DstAlpha,
    OneMinusDstAlpha,
};
enum class BlendOp : std::uint8_t { Add, Subtract, ReverseSubtract, Min, Max };

// How a colour target blends the fragment with what it holds.
struct BlendState {
    bool enable = false;
    BlendFactor srcColor = BlendFactor::One;
    BlendFactor dstColor = BlendFactor::Zero;
    BlendOp colorOp = BlendOp::Add;
    BlendFactor srcAlpha = BlendFactor::One;
    BlendFactor dstAlpha = BlendFactor::Zero;
    BlendOp alphaOp = BlendOp::Add;
};

// One colour attachment of a pipeline: its format, blending and write mask.
struct ColorTarget {
    Format format = Format::RGBA8;
    ColorMask writeMask = ColorMask::All;
    BlendState blend;
};

// A pipeline renders into framebuffers whose attachment formats match colorTargets and depthFormat and whose
// sample count is `samples` (checked at each draw). A depth-only pass has no colour targets; at most 8 colour targets.
// Every attribute reads a vertex buffer slot the layout describes, and every draw needs those slots bound.
// uniformLayouts describe the C++ structs uploaded into uniform blocks: at creation each is compared with the
// std140 layout the shaders' reflection gives the block of that name (size, member names, offsets, sizes).
struct PipelineDesc {
    const Shader* vertex = nullptr;
    const Shader* fragment = nullptr;
    VertexLayout vertexLayout;
    PrimitiveTopology topology = PrimitiveTopology::TriangleList;
    CullMode cull = CullMode::None;
    DepthState depth;
    std::vector<ColorTarget> colorTargets;
    std::optional<Format> depthFormat;
    // Rasterization samples: the framebuffer's TextureDesc::samples, one the device offers for every target
    // format (Capabilities::sampleCounts). The fragment shader runs once per pixel and its output goes to the
    // samples the primitive covers (multisampling, Vulkan 1.3 section 28.4; GL 4.5 section 14.3.1).
    std::uint32_t samples = 1;
    std::vector<UniformLayout> uniformLayouts;
    // The C++ structs in storage blocks the stages read, compared with their std430 layout as uniformLayouts are.
    std::vector<UniformLayout> storageLayouts;
    // The layouts of the binding sets the pipeline is drawn with, no binding number in two of them, each binding the
    // shaders declare there of the layout's kind. A set of one of them is bound with one call on every backend that
    // has descriptor sets (Vulkan: one descriptor set per layout); other bindings, and sets of layouts not listed,
    // are bound per draw. The layouts may be destroyed once the pipeline exists.
    std::vector<const BindingSetLayout*> bindingSetLayouts;
    std::string debugName;
};

// Shaders and fixed state, drawn with inside a pass whose framebuffer matches its formats.
class Pipeline : private LiveObject<ObjectKind::Pipeline> {
public:
    virtual ~Pipeline() = default;
    // The description the pipeline was created with.
    virtual const PipelineDesc& desc() const = 0;
    // Every binding both stages declare, sorted by number: what a draw needs bound (uniform blocks with at
    // least their reflected size, textures with a sampler).
    virtual const std::vector<ShaderBinding>& bindings() const = 0;
};

// A compute shader and the C++ layouts of its blocks: uniformLayouts against the std140 layout reflection gives, as
// for PipelineDesc; storageLayouts against the std430 layout of storage blocks (a runtime array member, `T data[]`,
// is described by its element: PENUMBRA_UNIFORM_ARRAY_ELEMENT). The workgroup size comes from the shader's
// `layout(local_size_x = ...)` and must be within Capabilities' workgroup limits, as its shared memory.
struct ComputePipelineDesc {
    const Shader* compute = nullptr;
    std::vector<UniformLayout> uniformLayouts;
    std::vector<UniformLayout> storageLayouts;
    std::vector<const BindingSetLayout*> bindingSetLayouts; // as PipelineDesc's
    std::string debugName;
};

// A compute shader ready to dispatch (CommandList::bindComputePipeline, dispatch, dispatchIndirect). As with
// Pipeline, the shader may be destroyed once the pipeline exists.
class ComputePipeline : private LiveObject<ObjectKind::Pipeline> {
public:
    virtual ~ComputePipeline() = default;
    // The description the pipeline was created with.
    virtual const ComputePipelineDesc& desc() const = 0;
    // Every binding the shader declares, sorted by number: what a dispatch needs bound.
    const std::vector<ShaderBinding>& bindings() const { return bindings_; }
    // Invocations per workgroup along x, y and z, from the shader's local_size.
    const std::array<std::uint32_t, 3>& workgroupSize() const { return workgroupSize_; }

protected:
    explicit ComputePipeline(const CompiledShader& shader);

private:
    std::vector<ShaderBinding> bindings_;
    std::array<std::uint32_t, 3> workgroupSize_;
};

} // namespace penumbra::rhi
