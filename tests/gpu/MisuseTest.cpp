// The rules of the RHI's validation layer (rhi/src/validation), one row each: the calls before the rule is
// broken, the one call that breaks it, and the error it raises there. Every configuration runs the whole table
// and must raise the same exception type with the same text at the same call, so the table is also the
// documentation of the rules (README, "Validation rules").
#include "GpuTesting.hpp"

#include "penumbra/rhi/Error.hpp"

#include <array>
#include <cstddef>
#include <fmt/format.h>
#include <functional>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <initializer_list>
#include <span>
#include <typeinfo>
#include <vector>

namespace penumbra::testing {
namespace {

const char* const tintVertexGlsl = R"(#version 450
layout(location = 0) in vec3 position;
layout(std140, binding = 0) uniform Transform {
    mat4 clip;
    vec4 tint;
} transform;
layout(location = 0) out vec4 tint;
void main() { gl_Position = transform.clip * vec4(position, 1.0); tint = transform.tint; }
)";

const char* const tintedTextureGlsl = R"(#version 450
layout(location = 0) in vec4 tint;
layout(binding = 1) uniform sampler2D image;
layout(location = 0) out vec4 color;
void main() { color = tint * texture(image, vec2(0.5)); }
)";

// Binding 0 is a texture here but the vertex shader's uniform block.
const char* const conflictingFragmentGlsl = R"(#version 450
layout(binding = 0) uniform sampler2D image;
layout(location = 0) out vec4 color;
void main() { color = texture(image, vec2(0.5)); }
)";

const char* const depthOnlyFragmentGlsl = "#version 450\nvoid main() {}\n";

const char* const computeGlsl = R"(#version 450
layout(local_size_x = 4) in;
layout(std430, binding = 0) buffer Data { uint first; uint count; uint values[]; } data;
layout(binding = 1, rgba8) uniform image2D image;
void main()
{
    data.values[gl_GlobalInvocationID.x] = data.first + data.count;
    imageStore(image, ivec2(0), vec4(1.0));
}
)";

// 32 x 32 x 2 = 2048 invocations: each size within glslang's limits, the whole over every device's 1024.
const char* const bigComputeGlsl =
    "#version 450\nlayout(local_size_x = 32, local_size_y = 32, local_size_z = 2) in;\nvoid main() {}\n";

// A fragment shader that writes a storage block.
const char* const writingFragmentGlsl = R"(#version 450
layout(std430, binding = 2) buffer Counts { uint fragments; } counts;
layout(location = 0) out vec4 color;
void main() { atomicAdd(counts.fragments, 1u); color = vec4(1.0); }
)";

// The C++ twin of Data's header, wrong: `count` where `first` is.
struct MisplacedDataHeader {
    std::uint32_t count;
    std::uint32_t first;
};

// The C++ twin of Transform, right and wrong.
struct TransformUniforms {
    glm::mat4 clip{1.0f};
    glm::vec4 tint{1.0f};
};
struct MisplacedTransformUniforms {
    glm::mat4 clip{1.0f};
    float scale = 1.0f;
    glm::vec4 tint{1.0f};
};

rhi::UniformLayout transformLayout()
{
    return {"Transform",
            sizeof(TransformUniforms),
            {PENUMBRA_UNIFORM_MEMBER(TransformUniforms, clip), PENUMBRA_UNIFORM_MEMBER(TransformUniforms, tint)}};
}

// The sample count of the fixture's multisampled textures: the lowest above 1 the device offers for RGBA8 and D32F
// targets (MultisampleTest checks there is one).
std::uint32_t multisampleCount(const rhi::Capabilities& caps)
{
    const std::array targets{rhi::Format::RGBA8, rhi::Format::D32F};
    return lowestMultisampleCount(caps, targets);
}

// What every row starts from: one device's resources for a draw into an 8x8 RGBA8 + D32F target, and a fresh
// command list.
struct Objects {
    explicit Objects(rhi::Device& d) : device(d)
    {
        list = device.createCommandList();
        vertices = device.createBuffer({.size = 36, .usage = rhi::BufferUsage::Vertex, .debugName = "vertices"});
        indices = device.createBuffer({.size = 6, .usage = rhi::BufferUsage::Index, .debugName = "indices"});
        uniforms = device.createBuffer({.size = 256, .usage = rhi::BufferUsage::Uniform, .debugName = "uniforms"});
        readback = device.createBuffer({.size = 512, .usage = rhi::BufferUsage::Readback, .debugName = "readback"});
        color = device.createTexture({.width = 8,
                                      .height = 8,
                                      .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                      .debugName = "color"});
        depth = device.createTexture({.width = 8,
                                      .height = 8,
                                      .format = rhi::Format::D32F,
                                      .usage = rhi::TextureUsage::RenderTarget,
                                      .debugName = "depth"});
        image =
            device.createTexture({.width = 4, .height = 4, .usage = rhi::TextureUsage::Sampled, .debugName = "image"});
        small = device.createTexture(
            {.width = 4, .height = 4, .usage = rhi::TextureUsage::RenderTarget, .debugName = "small"});
        sampler = device.createSampler(
            {.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest, .debugName = "nearest"});
        vertex = device.createShader({rhi::ShaderStage::Vertex, tintVertexGlsl, "misuse.vert"});
        fragment = device.createShader({rhi::ShaderStage::Fragment, tintedTextureGlsl, "misuse.frag"});
        const rhi::Attachment colorAttachment{color.get(), 0};
        target = device.createFramebuffer(
            {.colors = {&colorAttachment, 1}, .depth = {depth.get(), 0}, .debugName = "target"});
        pipeline = device.createPipeline(pipelineDesc());
        const std::uint32_t samples = multisampleCount(device.capabilities());
        multisampled = device.createTexture({.width = 8,
                                             .height = 8,
                                             .usage = rhi::TextureUsage::RenderTarget,
                                             .samples = samples,
                                             .debugName = "multisampled"});
        multisampledDepth = device.createTexture({.width = 8,
                                                  .height = 8,
                                                  .format = rhi::Format::D32F,
                                                  .usage = rhi::TextureUsage::RenderTarget,
                                                  .samples = samples,
                                                  .debugName = "multisampled depth"});
        const rhi::Attachment multisampledAttachment{multisampled.get(), 0};
        multisampledTarget = device.createFramebuffer({.colors = {&multisampledAttachment, 1},
                                                       .depth = {multisampledDepth.get(), 0},
                                                       .debugName = "multisampled target"});
    }

    rhi::PipelineDesc pipelineDesc() const
    {
        rhi::PipelineDesc desc;
        desc.vertex = vertex.get();
        desc.fragment = fragment.get();
        desc.vertexLayout = {{{.stride = 12}}, {{.location = 0, .format = rhi::VertexFormat::Float3}}};
        desc.colorTargets = {{.format = rhi::Format::RGBA8}};
        desc.depthFormat = rhi::Format::D32F;
        desc.uniformLayouts = {transformLayout()};
        desc.debugName = "bad";
        return desc;
    }

    void beginPass() { list->beginPass({.framebuffer = target.get()}); }
    void barriers(std::initializer_list<rhi::ResourceBarrier> items)
    {
        list->resourceBarriers(std::span(items.begin(), items.size()));
    }
    // A pass with everything `pipeline` reads bound, but for `except` ("vertex", "uniform", "texture").
    void bindForDraw(std::string_view except = "")
    {
        beginPass();
        list->bindPipeline(*pipeline);
        if (except != "vertex")
            list->bindVertexBuffer(0, *vertices);
        if (except != "uniform")
            list->bindUniformBuffer(0, *uniforms, 0, sizeof(TransformUniforms));
        if (except != "texture")
            list->bindTexture(1, *image, *sampler);
    }

    // The compute objects, made for the rows that use them: a pipeline reading a storage buffer at binding 0 and a
    // storage image at binding 1, a 64-byte storage buffer, a 12-byte indirect buffer and a 4x4 storage texture.
    void makeCompute()
    {
        computeShader = device.createShader({rhi::ShaderStage::Compute, computeGlsl, "misuse.comp"});
        computePipeline = device.createComputePipeline({.compute = computeShader.get(), .debugName = "compute"});
        storage = device.createBuffer({.size = 64, .usage = rhi::BufferUsage::Storage, .debugName = "storage"});
        indirect = device.createBuffer({.size = 12, .usage = rhi::BufferUsage::Indirect, .debugName = "indirect"});
        storageImage = device.createTexture(
            {.width = 4, .height = 4, .usage = rhi::TextureUsage::Storage, .debugName = "storage image"});
    }
    // The compute pipeline bound with everything it reads, but for `except` ("buffer", "image").
    void bindForDispatch(std::string_view except = "")
    {
        makeCompute();
        list->bindComputePipeline(*computePipeline);
        if (except != "buffer")
            list->bindStorageBuffer(0, *storage, 0, 64);
        if (except != "image")
            list->bindStorageTexture(1, *storageImage);
    }

    // A binding set layout of the fixture pipeline's bindings: its uniform block at 0, its texture at 1.
    void makeLayout()
    {
        layout = device.createBindingSetLayout(
            {.items = {{0, rhi::BindingKind::UniformBuffer}, {1, rhi::BindingKind::SampledTexture}},
             .debugName = "fixture"});
    }

    // A pass with a pipeline that reads vertex buffer slot 0 per instance (three instances fit `vertices`), all it
    // reads bound, and `indices`.
    void bindForInstancedDraw()
    {
        rhi::PipelineDesc d = pipelineDesc();
        d.vertexLayout.buffers[0].perInstance = true;
        localPipeline = device.createPipeline(d);
        beginPass();
        list->bindPipeline(*localPipeline);
        list->bindVertexBuffer(0, *vertices);
        list->bindIndexBuffer(*indices, rhi::IndexType::UInt16);
        list->bindUniformBuffer(0, *uniforms, 0, sizeof(TransformUniforms));
        list->bindTexture(1, *image, *sampler);
    }

    rhi::Device& device;
    std::unique_ptr<rhi::Buffer> vertices, indices, uniforms, readback;
    std::unique_ptr<rhi::Texture> color, depth, image, small;
    std::unique_ptr<rhi::Texture> multisampled, multisampledDepth; // 8x8 RGBA8 and D32F, multisampleCount samples
    std::unique_ptr<rhi::Sampler> sampler;
    std::unique_ptr<rhi::Shader> vertex, fragment, localShader;
    std::unique_ptr<rhi::Framebuffer> target, multisampledTarget;
    std::unique_ptr<rhi::Pipeline> pipeline, localPipeline; // localPipeline: a row's own
    std::unique_ptr<rhi::Shader> computeShader;
    std::unique_ptr<rhi::ComputePipeline> computePipeline;
    std::unique_ptr<rhi::Buffer> storage, indirect;
    std::unique_ptr<rhi::Texture> storageImage, localTexture; // localTexture, localBuffer: a row's own
    std::unique_ptr<rhi::Buffer> localBuffer;
    std::unique_ptr<rhi::BindingSetLayout> layout;
    std::unique_ptr<rhi::BindingSet> set;
    std::unique_ptr<rhi::CommandList> list; // last: it goes first, before what it names
};

enum class Raises { Error, Unsupported };

struct Rule {
    const char* rule;
    // Everything before the breaking call; must not throw.
    std::function<void(Objects&)> setup;
    // The one call that breaks the rule.
    std::function<void(Objects&)> breaking;
    Raises raises;
    // The text, from the device's capabilities where the rule quotes a limit.
    std::function<std::string(const rhi::Capabilities&)> message;
};

auto text(std::string message)
{
    return [message](const rhi::Capabilities&) { return message; };
}
void nothing(Objects&) {}

rhi::Attachment attach(const std::unique_ptr<rhi::Texture>& texture, std::uint32_t layer = 0)
{
    return {texture.get(), layer};
}

const std::vector<Rule>& rules()
{
    using E = Raises;
    using S = rhi::ResourceState;
    static const std::vector<Rule> table{
        // Descriptors.
        {"texture sizes are 1..maxTextureSize", nothing,
         [](Objects& o) { o.device.createTexture({.width = 0, .height = 8, .debugName = "bad"}); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("texture 'bad': 0x8 with 1 layers is outside 1..{} texels and 1..{} layers",
                                c.maxTextureSize, c.maxTextureLayers);
         }},
        {"mip levels are 1..fullMipChain", nothing,
         [](Objects& o) { o.device.createTexture({.width = 8, .height = 8, .mipLevels = 5, .debugName = "bad"}); },
         E::Error, text("texture 'bad': mipLevels 5 is outside 1..4 (the full chain of 8x8)")},
        {"a texture has at least one mip level", nothing,
         [](Objects& o) { o.device.createTexture({.width = 8, .height = 8, .mipLevels = 0, .debugName = "bad"}); },
         E::Error, text("texture 'bad': mipLevels 0 is outside 1..4 (the full chain of 8x8)")},
        {"cube textures have 6 layers per cube", nothing,
         [](Objects& o) {
             o.device.createTexture({.width = 8, .height = 8, .layers = 4, .cube = true, .debugName = "bad"});
         },
         E::Error, text("texture 'bad': a cube texture needs a multiple of 6 layers (one per face), not 4")},
        {"cube faces are square", nothing,
         [](Objects& o) {
             o.device.createTexture({.width = 8, .height = 4, .layers = 6, .cube = true, .debugName = "bad"});
         },
         E::Error, text("texture 'bad': a cube texture needs square faces, not 8x4")},
        {"sampler LOD clamps are ordered", nothing,
         [](Objects& o) { o.device.createSampler({.minLod = 2.0f, .maxLod = 1.0f, .debugName = "bad"}); }, E::Error,
         text("sampler 'bad': minLod 2 and maxLod 1 must satisfy 0 <= minLod <= maxLod")},
        {"sampler anisotropy is 1..maxSamplerAnisotropy", nothing,
         [](Objects& o) { o.device.createSampler({.maxAnisotropy = 0.5f, .debugName = "bad"}); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("sampler 'bad': maxAnisotropy 0.5 is outside [1, {}], the limit of {}",
                                c.maxSamplerAnisotropy, c.device);
         }},
        {"a framebuffer has an attachment", nothing,
         [](Objects& o) { o.device.createFramebuffer({.debugName = "bad"}); }, E::Error,
         text("framebuffer 'bad' has no attachments")},
        {"colour attachments have colour formats", nothing,
         [](Objects& o) {
             const rhi::Attachment a = attach(o.depth);
             o.device.createFramebuffer({.colors = {&a, 1}, .debugName = "bad"});
         },
         E::Error, text("framebuffer 'bad': texture 'depth' (D32F) cannot be a colour attachment")},
        {"attachments are RenderTarget textures", nothing,
         [](Objects& o) {
             const rhi::Attachment a = attach(o.image);
             o.device.createFramebuffer({.colors = {&a, 1}, .debugName = "bad"});
         },
         E::Error, text("framebuffer 'bad': texture 'image' lacks TextureUsage::RenderTarget")},
        {"attachment layers exist", nothing,
         [](Objects& o) {
             const rhi::Attachment a = attach(o.color, 1);
             o.device.createFramebuffer({.colors = {&a, 1}, .debugName = "bad"});
         },
         E::Error, text("framebuffer 'bad': layer 1 of texture 'color' is out of range [0, 0]")},
        {"attachments share one size", nothing,
         [](Objects& o) {
             const rhi::Attachment a[] = {attach(o.color), attach(o.small)};
             o.device.createFramebuffer({.colors = a, .debugName = "bad"});
         },
         E::Error, text("framebuffer 'bad': texture 'small' is 4x4 but 'color' is 8x8")},
        {"colour attachments name a texture", nothing,
         [](Objects& o) {
             const rhi::Attachment a{};
             o.device.createFramebuffer({.colors = {&a, 1}, .debugName = "bad"});
         },
         E::Error, text("framebuffer 'bad': a colour attachment has no texture")},
        {"a pipeline has both shaders", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.fragment = nullptr;
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad' needs a vertex and a fragment shader")},
        {"pipeline shaders are in their stages", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             std::swap(d.vertex, d.fragment);
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad': shader stages are swapped")},
        {"depthFormat is a depth format", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.depthFormat = rhi::Format::RGBA8;
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad': depthFormat RGBA8 is not a depth format")},
        {"colour targets have colour formats", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.colorTargets = {{.format = rhi::Format::D32F}};
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad': colour target format D32F is a depth format")},
        {"at most 8 colour targets", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.colorTargets.resize(9);
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad': 9 colour targets, at most 8")},
        {"attributes read slots the vertex layout describes", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.vertexLayout.attributes[0].buffer = 1;
             o.device.createPipeline(d);
         },
         E::Error,
         text(
             "pipeline 'bad': attribute at location 0 reads vertex buffer slot 1, but the layout describes 1 buffer(s)")},
        {"both stages give a binding the same kind", nothing,
         [](Objects& o) {
             auto conflicting =
                 o.device.createShader({rhi::ShaderStage::Fragment, conflictingFragmentGlsl, "conflict.frag"});
             rhi::PipelineDesc d = o.pipelineDesc();
             d.fragment = conflicting.get();
             d.uniformLayouts.clear();
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad': binding 0 is 'Transform' in misuse.vert but 'image' in conflict.frag")},
        {"C++ uniform layouts match the std140 offsets", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.uniformLayouts = {{"Transform",
                                  sizeof(MisplacedTransformUniforms),
                                  {PENUMBRA_UNIFORM_MEMBER(MisplacedTransformUniforms, clip),
                                   PENUMBRA_UNIFORM_MEMBER(MisplacedTransformUniforms, tint)}}};
             o.device.createPipeline(d);
         },
         E::Error,
         text("pipeline 'bad': uniform block 'Transform' member 'tint' is at offset 64 in misuse.vert but at offset 68 "
              "in C++")},
        {"C++ uniform layouts have every member of the block", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.uniformLayouts = {
                 {"Transform", sizeof(TransformUniforms), {PENUMBRA_UNIFORM_MEMBER(TransformUniforms, clip)}}};
             o.device.createPipeline(d);
         },
         E::Error,
         text("pipeline 'bad': uniform block 'Transform' member 'tint' (offset 64 in misuse.vert) is missing from the "
              "C++ layout")},
        {"C++ uniform layouts have the block's size", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.uniformLayouts[0].size = 96;
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad': uniform block 'Transform' is 80 bytes in misuse.vert but 96 bytes in C++")},
        {"C++ uniform layouts name a block of the shaders", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.uniformLayouts[0].block = "Missing";
             o.device.createPipeline(d);
         },
         E::Error,
         text(
             "pipeline 'bad': the C++ layout of uniform block 'Missing' matches no block of misuse.vert or misuse.frag")},
        {"timestamp queries count at least one", nothing, [](Objects& o) { o.device.createTimestampQueries(0); },
         E::Error, text("createTimestampQueries: count must be at least 1")},
        // Multisampling.
        {"sample counts are 1, 2, 4 or 8", nothing,
         [](Objects& o) {
             o.device.createTexture(
                 {.width = 8, .height = 8, .usage = rhi::TextureUsage::RenderTarget, .samples = 3, .debugName = "bad"});
         },
         E::Error, text("texture 'bad': samples 3 is not 1, 2, 4 or 8")},
        {"multisampled textures are render targets only", nothing,
         [](Objects& o) {
             o.device.createTexture({.width = 8,
                                     .height = 8,
                                     .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                     .samples = multisampleCount(o.device.capabilities()),
                                     .debugName = "bad"});
         },
         E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("texture 'bad': a multisampled texture ({} samples) is a RenderTarget and not Sampled "
                                "(resolveTexture makes a texture to sample)",
                                multisampleCount(c));
         }},
        {"multisampled textures have one layer and one level", nothing,
         [](Objects& o) {
             o.device.createTexture({.width = 8,
                                     .height = 8,
                                     .layers = 2,
                                     .usage = rhi::TextureUsage::RenderTarget,
                                     .samples = multisampleCount(o.device.capabilities()),
                                     .debugName = "bad"});
         },
         E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("texture 'bad': a multisampled texture ({} samples) has one layer and one mip level, "
                                "not 2 layers and 1 levels",
                                multisampleCount(c));
         }},
        {"framebuffer attachments share one sample count", nothing,
         [](Objects& o) {
             const rhi::Attachment a = attach(o.multisampled);
             o.device.createFramebuffer({.colors = {&a, 1}, .depth = attach(o.depth), .debugName = "bad"});
         },
         E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("framebuffer 'bad': texture 'depth' has 1 sample(s) but 'multisampled' has {}",
                                multisampleCount(c));
         }},
        {"pipeline sample counts are 1, 2, 4 or 8", nothing,
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.samples = 5;
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad': samples 5 is not 1, 2, 4 or 8")},
        {"a pipeline draws with its framebuffer's sample count",
         [](Objects& o) {
             o.list->beginPass({.framebuffer = o.multisampledTarget.get()});
             o.list->bindPipeline(*o.pipeline);
             o.list->bindVertexBuffer(0, *o.vertices);
             o.list->bindUniformBuffer(0, *o.uniforms, 0, sizeof(TransformUniforms));
             o.list->bindTexture(1, *o.image, *o.sampler);
         },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("draw: pipeline 'bad' draws with 1 sample(s), but the pass's framebuffer has {}",
                                multisampleCount(c));
         }},
        {"resolve reads a multisampled texture", nothing,
         [](Objects& o) { o.list->resolveTexture(*o.color, *o.small); }, E::Error,
         text("resolveTexture: source 'color' is not multisampled")},
        {"resolve reads colour", nothing, [](Objects& o) { o.list->resolveTexture(*o.multisampledDepth, *o.depth); },
         E::Error, text("resolveTexture: source 'multisampled depth' is D32F; only colour textures are resolved")},
        {"resolve writes a single-sampled texture", nothing,
         [](Objects& o) { o.list->resolveTexture(*o.multisampled, *o.multisampled); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("resolveTexture: destination 'multisampled' is multisampled ({} samples)",
                                multisampleCount(c));
         }},
        {"resolve writes a render target", nothing,
         [](Objects& o) { o.list->resolveTexture(*o.multisampled, *o.image); }, E::Error,
         text("resolveTexture: destination 'image' must be a RenderTarget texture of one layer")},
        {"resolve keeps size and format", nothing,
         [](Objects& o) { o.list->resolveTexture(*o.multisampled, *o.small); }, E::Error,
         text("resolveTexture: 'multisampled' is 8x8 RGBA8 but 'small' is 4x4 RGBA8")},
        {"resolve is outside passes", [](Objects& o) { o.beginPass(); },
         [](Objects& o) { o.list->resolveTexture(*o.multisampled, *o.color); }, E::Error,
         text("resolveTexture: not allowed inside a pass; call endPass() first")},
        {"multisampled textures are not read back", nothing,
         [](Objects& o) { o.list->copyTextureToBuffer(*o.multisampled, 0, 0, *o.readback); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("copyTextureToBuffer: texture 'multisampled' is multisampled ({} samples); "
                                "resolveTexture gives a single-sampled texture",
                                multisampleCount(c));
         }},
        {"multisampled textures are not uploaded", nothing,
         [](Objects& o) { o.device.writeTexture(*o.multisampled, 0, 0, std::vector<std::byte>(256)); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("writeTexture: texture 'multisampled' is multisampled ({} samples); resolveTexture "
                                "gives a single-sampled texture",
                                multisampleCount(c));
         }},
        {"multisampled textures are not copied", nothing,
         [](Objects& o) { o.list->copyTexture(*o.multisampled, 0, *o.color, 0); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("copyTexture source: texture 'multisampled' is multisampled ({} samples); "
                                "resolveTexture gives a single-sampled texture",
                                multisampleCount(c));
         }},
        // Uploads and CPU access.
        {"an upload is one whole level", nothing,
         [](Objects& o) {
             const std::vector<std::byte> bytes(4);
             o.device.writeTexture(*o.color, 0, 0, bytes);
         },
         E::Error, text("writeTexture: level 0 of 'color' (8x8 RGBA8) takes 256 bytes, got 4")},
        {"an upload's layer exists", nothing,
         [](Objects& o) {
             const std::vector<std::byte> bytes(256);
             o.device.writeTexture(*o.color, 1, 0, bytes);
         },
         E::Error, text("writeTexture: layer 1 of texture 'color' is out of range [0, 0]")},
        {"buffer writes stay inside the buffer", nothing,
         [](Objects& o) {
             const std::vector<std::byte> bytes(8);
             o.uniforms->write(252, bytes);
         },
         E::Error, text("Buffer::write: 8 bytes at offset 252 exceed buffer 'uniforms' (256 bytes)")},
        {"buffer reads stay inside the buffer", nothing,
         [](Objects& o) {
             std::vector<std::byte> bytes(8);
             o.vertices->read(32, bytes);
         },
         E::Error, text("Buffer::read: 8 bytes at offset 32 exceed buffer 'vertices' (36 bytes)")},
        // Pass state.
        {"a pass has a framebuffer", nothing, [](Objects& o) { o.list->beginPass({}); }, E::Error,
         text("beginPass: PassDesc::framebuffer is null")},
        {"passes do not nest", [](Objects& o) { o.beginPass(); }, [](Objects& o) { o.beginPass(); }, E::Error,
         text("beginPass: a pass is already open; call endPass() first")},
        {"endPass ends an open pass", nothing, [](Objects& o) { o.list->endPass(); }, E::Error,
         text("endPass: no pass is open")},
        {"draws are inside a pass", [](Objects& o) { o.list->bindPipeline(*o.pipeline); },
         [](Objects& o) { o.list->draw(3); }, E::Error, text("draw: not inside a pass; call beginPass() first")},
        {"draws need a pipeline", [](Objects& o) { o.beginPass(); }, [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: no pipeline is bound; call bindPipeline() first")},
        {"copies are outside passes: copyBuffer", [](Objects& o) { o.beginPass(); },
         [](Objects& o) { o.list->copyBuffer(*o.vertices, 0, *o.readback, 0, 4); }, E::Error,
         text("copyBuffer: not allowed inside a pass; call endPass() first")},
        {"copies are outside passes: copyTexture", [](Objects& o) { o.beginPass(); },
         [](Objects& o) { o.list->copyTexture(*o.image, 0, *o.small, 0); }, E::Error,
         text("copyTexture: not allowed inside a pass; call endPass() first")},
        {"copies are outside passes: copyTextureToBuffer", [](Objects& o) { o.beginPass(); },
         [](Objects& o) { o.list->copyTextureToBuffer(*o.image, 0, 0, *o.readback); }, E::Error,
         text("copyTextureToBuffer: not allowed inside a pass; call endPass() first")},
        {"submitted lists are outside passes", [](Objects& o) { o.beginPass(); },
         [](Objects& o) { o.device.submit(*o.list); }, E::Error,
         text("submit: the command list is inside a pass; call endPass() first")},
        {"popLabel closes an open label", nothing, [](Objects& o) { o.list->popLabel(); }, E::Error,
         text("popLabel: no label is open")},
        {"submitted lists have closed their labels", [](Objects& o) { o.list->pushLabel("shadows"); },
         [](Objects& o) { o.device.submit(*o.list); }, E::Error,
         text("submit: label 'shadows' is still open; call popLabel() first")},
        // Pipelines against the pass and what is bound, checked at each draw.
        {"pipelines draw into framebuffers of their formats",
         [](Objects& o) {
             o.bindForDraw();
             o.localShader = o.device.createShader({rhi::ShaderStage::Fragment, depthOnlyFragmentGlsl, "depth.frag"});
             rhi::PipelineDesc d = o.pipelineDesc();
             d.fragment = o.localShader.get();
             d.colorTargets.clear();
             d.debugName = "depth only";
             o.localPipeline = o.device.createPipeline(d);
             o.list->bindPipeline(*o.localPipeline);
         },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: pipeline 'depth only' renders to depth D32F, but the pass's framebuffer has RGBA8, depth D32F")},
        {"uniform blocks are bound at draws", [](Objects& o) { o.bindForDraw("uniform"); },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: pipeline 'bad' binding 0 ('Transform') needs a uniform buffer, but nothing is bound")},
        {"uniform blocks are bound with buffers",
         [](Objects& o) {
             o.bindForDraw("uniform");
             o.list->bindTexture(0, *o.image, *o.sampler);
         },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: pipeline 'bad' binding 0 ('Transform') needs a uniform buffer, but a texture is bound")},
        {"bound uniform ranges cover the block",
         [](Objects& o) {
             o.bindForDraw("uniform");
             o.list->bindUniformBuffer(0, *o.uniforms, 0, 16);
         },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: pipeline 'bad' binding 0 ('Transform') is a uniform block of 80 bytes, but 16 bytes are bound")},
        {"textures are bound at draws", [](Objects& o) { o.bindForDraw("texture"); },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: pipeline 'bad' binding 1 ('image') needs a texture and sampler, but nothing is bound")},
        {"vertex buffer slots are bound at draws", [](Objects& o) { o.bindForDraw("vertex"); },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: pipeline 'bad' reads vertex buffer slot 0, which is not bound")},
        {"indexed draws need an index buffer", [](Objects& o) { o.bindForDraw(); },
         [](Objects& o) { o.list->drawIndexed(3); }, E::Error,
         text("drawIndexed: no index buffer is bound; call bindIndexBuffer() first")},
        {"per-instance vertex buffers hold every instance drawn", [](Objects& o) { o.bindForInstancedDraw(); },
         [](Objects& o) { o.list->draw(3, 4); }, E::Error,
         text("draw: pipeline 'bad' reads instances 0 to 3 from vertex buffer slot 0 (48 bytes), but 36 bytes are "
              "bound there")},
        {"per-instance vertex buffers hold every instance drawn: indexed draws, from firstInstance",
         [](Objects& o) { o.bindForInstancedDraw(); }, [](Objects& o) { o.list->drawIndexed(3, 2, 0, 0, 2); }, E::Error,
         text("drawIndexed: pipeline 'bad' reads instances 2 to 3 from vertex buffer slot 0 (48 bytes), but 36 bytes "
              "are bound there")},
        // Usages and ranges at bind time.
        {"vertex buffer slots are 0..15", nothing, [](Objects& o) { o.list->bindVertexBuffer(16, *o.vertices); },
         E::Error, text("bindVertexBuffer: slot 16 is outside 0..15")},
        {"vertex buffers have BufferUsage::Vertex", nothing,
         [](Objects& o) { o.list->bindVertexBuffer(0, *o.uniforms); }, E::Error,
         text("bindVertexBuffer: buffer 'uniforms' lacks BufferUsage::Vertex")},
        {"vertex buffer offsets are inside the buffer", nothing,
         [](Objects& o) { o.list->bindVertexBuffer(0, *o.vertices, 40); }, E::Error,
         text("bindVertexBuffer: 0 bytes at offset 40 exceed buffer 'vertices' (36 bytes)")},
        {"index buffers have BufferUsage::Index", nothing,
         [](Objects& o) { o.list->bindIndexBuffer(*o.vertices, rhi::IndexType::UInt16); }, E::Error,
         text("bindIndexBuffer: buffer 'vertices' lacks BufferUsage::Index")},
        {"index buffer offsets are multiples of the index size", nothing,
         [](Objects& o) { o.list->bindIndexBuffer(*o.indices, rhi::IndexType::UInt16, 1); }, E::Error,
         text("bindIndexBuffer: offset 1 is not a multiple of the index size, 2 bytes")},
        {"uniform buffers have BufferUsage::Uniform", nothing,
         [](Objects& o) { o.list->bindUniformBuffer(0, *o.vertices, 0, 16); }, E::Error,
         text("bindUniformBuffer: buffer 'vertices' lacks BufferUsage::Uniform")},
        {"uniform ranges are at least a byte", nothing,
         [](Objects& o) { o.list->bindUniformBuffer(0, *o.uniforms, 0, 0); }, E::Error,
         text("bindUniformBuffer: binding 0: a uniform range needs at least 1 byte")},
        {"uniform ranges are at most maxUniformBufferRange", nothing,
         [](Objects& o) {
             o.list->bindUniformBuffer(0, *o.uniforms, 0, o.device.capabilities().maxUniformBufferRange + 16ull);
         },
         E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format(
                 "bindUniformBuffer: binding 0: {} bytes exceed Capabilities::maxUniformBufferRange ({})",
                 c.maxUniformBufferRange + 16ull, c.maxUniformBufferRange);
         }},
        {"uniform ranges are inside the buffer", nothing,
         [](Objects& o) { o.list->bindUniformBuffer(0, *o.uniforms, 0, 512); }, E::Error,
         text("bindUniformBuffer: 512 bytes at offset 0 exceed buffer 'uniforms' (256 bytes)")},
        {"uniform offsets are aligned", nothing, [](Objects& o) { o.list->bindUniformBuffer(0, *o.uniforms, 1, 16); },
         E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("bindUniformBuffer: offset 1 is not a multiple of "
                                "Capabilities::uniformBufferOffsetAlignment ({})",
                                c.uniformBufferOffsetAlignment);
         }},
        {"bound textures have TextureUsage::Sampled", nothing,
         [](Objects& o) { o.list->bindTexture(1, *o.small, *o.sampler); }, E::Error,
         text("bindTexture: texture 'small' lacks TextureUsage::Sampled")},
        // Copies.
        {"buffer copies stay inside the source", nothing,
         [](Objects& o) { o.list->copyBuffer(*o.vertices, 0, *o.readback, 0, 64); }, E::Error,
         text("copyBuffer source: 64 bytes at offset 0 exceed buffer 'vertices' (36 bytes)")},
        {"buffer copies stay inside the destination", nothing,
         [](Objects& o) { o.list->copyBuffer(*o.readback, 0, *o.vertices, 0, 64); }, E::Error,
         text("copyBuffer destination: 64 bytes at offset 0 exceed buffer 'vertices' (36 bytes)")},
        {"texture copies are between equal textures", nothing,
         [](Objects& o) { o.list->copyTexture(*o.color, 0, *o.small, 0); }, E::Error,
         text("copyTexture: 'color' is 8x8 RGBA8 with 1 levels but 'small' is 4x4 RGBA8 with 1 levels")},
        {"a texture layer is not copied onto itself", nothing,
         [](Objects& o) { o.list->copyTexture(*o.image, 0, *o.image, 0); }, E::Error,
         text("copyTexture: layer 0 of 'image' onto itself")},
        {"readbacks fit the buffer", nothing,
         [](Objects& o) { o.list->copyTextureToBuffer(*o.color, 0, 0, *o.vertices); }, E::Error,
         text("copyTextureToBuffer: 256 bytes at offset 0 exceed buffer 'vertices' (36 bytes)")},
        {"readback offsets are texel-aligned", nothing,
         [](Objects& o) { o.list->copyTextureToBuffer(*o.color, 0, 0, *o.readback, 2); }, E::Error,
         text("copyTextureToBuffer: offset 2 is not a multiple of 4 for RGBA8")},
        {"readback levels exist", nothing, [](Objects& o) { o.list->copyTextureToBuffer(*o.color, 0, 1, *o.readback); },
         E::Error, text("copyTextureToBuffer: mip level 1 of texture 'color' is out of range [0, 0]")},
        {"timestamp indices exist", nothing,
         [](Objects& o) {
             auto queries = o.device.createTimestampQueries(2);
             o.list->writeTimestamp(*queries, 2);
         },
         E::Error, text("writeTimestamp: index 2 is out of range [0, 1]")},
        // Compute, storage and indirect commands.
        {"dispatches happen outside passes",
         [](Objects& o) {
             o.bindForDispatch();
             o.beginPass();
         },
         [](Objects& o) { o.list->dispatch(1); }, E::Error,
         text("dispatch: not allowed inside a pass; call endPass() first")},
        {"dispatches need a compute pipeline", nothing, [](Objects& o) { o.list->dispatch(1); }, E::Error,
         text("dispatch: no compute pipeline is bound; call bindComputePipeline() first")},
        {"dispatches bind what the pipeline reads", [](Objects& o) { o.bindForDispatch("buffer"); },
         [](Objects& o) { o.list->dispatch(1); }, E::Error,
         text("dispatch: pipeline 'compute' binding 0 ('Data') needs a storage buffer, but nothing is bound")},
        {"storage blocks get their fixed part", [](Objects& o) { o.bindForDispatch(); },
         [](Objects& o) {
             o.list->bindStorageBuffer(0, *o.storage, 0, 4);
             o.list->dispatch(1);
         },
         E::Error,
         text("dispatch: pipeline 'compute' binding 0 ('Data') is a storage block of 8 bytes, but 4 bytes are bound")},
        {"storage images have the shader's format",
         [](Objects& o) {
             o.bindForDispatch("image");
             o.localTexture = o.device.createTexture({.width = 4,
                                                      .height = 4,
                                                      .format = rhi::Format::R32F,
                                                      .usage = rhi::TextureUsage::Storage,
                                                      .debugName = "r32f"});
             o.list->bindStorageTexture(1, *o.localTexture);
         },
         [](Objects& o) { o.list->dispatch(1); }, E::Error,
         text("dispatch: pipeline 'compute' binding 1 ('image') is a storage image of format RGBA8, but texture "
              "'r32f' is R32F")},
        {"dispatch counts are within Capabilities::maxWorkgroupCount", [](Objects& o) { o.bindForDispatch(); },
         [](Objects& o) { o.list->dispatch(o.device.capabilities().maxWorkgroupCount[0] + 1); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("dispatch: {} workgroups along x exceed Capabilities::maxWorkgroupCount ({})",
                                c.maxWorkgroupCount[0] + 1, c.maxWorkgroupCount[0]);
         }},
        {"workgroups are within Capabilities::maxWorkgroupInvocations", nothing,
         [](Objects& o) {
             o.device.createShader({rhi::ShaderStage::Compute, bigComputeGlsl, "big.comp"});
         },
         E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("big.comp: 32x32x2 = 2048 invocations per workgroup exceed "
                                "Capabilities::maxWorkgroupInvocations ({})",
                                c.maxWorkgroupInvocations);
         }},
        {"compute pipelines take a compute shader", nothing,
         [](Objects& o) { o.device.createComputePipeline({.compute = o.vertex.get(), .debugName = "bad"}); }, E::Error,
         text("compute pipeline 'bad': shader misuse.vert is not a compute shader")},
        {"C++ storage layouts match the std430 offsets", [](Objects& o) { o.makeCompute(); },
         [](Objects& o) {
             o.device.createComputePipeline(
                 {.compute = o.computeShader.get(),
                  .storageLayouts = {{"Data",
                                      sizeof(MisplacedDataHeader),
                                      {PENUMBRA_UNIFORM_MEMBER(MisplacedDataHeader, count),
                                       PENUMBRA_UNIFORM_MEMBER(MisplacedDataHeader, first),
                                       PENUMBRA_UNIFORM_ARRAY_ELEMENT(MisplacedDataHeader, values, std::uint32_t)}}},
                  .debugName = "bad"});
         },
         E::Error,
         text("pipeline 'bad': storage block 'Data' member 'first' is at offset 0 in misuse.comp but at "
              "offset 4 in C++")},
        {"vertex and fragment shaders only read storage blocks", nothing,
         [](Objects& o) {
             o.localShader = o.device.createShader({rhi::ShaderStage::Fragment, writingFragmentGlsl, "written.frag"});
             rhi::PipelineDesc d = o.pipelineDesc();
             d.fragment = o.localShader.get();
             o.device.createPipeline(d);
         },
         E::Error,
         text("pipeline 'bad': storage block 'Counts' in written.frag is not readonly: vertex and fragment shaders "
              "only read storage blocks")},
        {"storage bindings need BufferUsage::Storage", nothing,
         [](Objects& o) { o.list->bindStorageBuffer(0, *o.uniforms, 0, 16); }, E::Error,
         text("bindStorageBuffer: buffer 'uniforms' lacks BufferUsage::Storage")},
        {"storage ranges are inside the buffer", [](Objects& o) { o.makeCompute(); },
         [](Objects& o) { o.list->bindStorageBuffer(0, *o.storage, 0, 128); }, E::Error,
         text("bindStorageBuffer: 128 bytes at offset 0 exceed buffer 'storage' (64 bytes)")},
        {"storage offsets are aligned", [](Objects& o) { o.makeCompute(); },
         [](Objects& o) { o.list->bindStorageBuffer(0, *o.storage, 1, 16); }, E::Error,
         [](const rhi::Capabilities& c) {
             return fmt::format("bindStorageBuffer: offset 1 is not a multiple of "
                                "Capabilities::storageBufferOffsetAlignment ({})",
                                c.storageBufferOffsetAlignment);
         }},
        {"storage textures need TextureUsage::Storage", nothing,
         [](Objects& o) { o.list->bindStorageTexture(1, *o.image); }, E::Error,
         text("bindStorageTexture: texture 'image' lacks TextureUsage::Storage")},
        {"storage textures are one 2D layer", nothing,
         [](Objects& o) {
             o.device.createTexture(
                 {.width = 4, .height = 4, .layers = 2, .usage = rhi::TextureUsage::Storage, .debugName = "bad"});
         },
         E::Error, text("texture 'bad': a Storage texture is one 2D layer, not 2 layers")},
        {"indirect buffers need BufferUsage::Indirect", [](Objects& o) { o.bindForDispatch(); },
         [](Objects& o) { o.list->dispatchIndirect(*o.storage); }, E::Error,
         text("dispatchIndirect: buffer 'storage' lacks BufferUsage::Indirect")},
        {"indirect offsets are multiples of 4", [](Objects& o) { o.bindForDispatch(); },
         [](Objects& o) { o.list->dispatchIndirect(*o.indirect, 2); }, E::Error,
         text("dispatchIndirect: offset 2 is not a multiple of 4")},
        {"indirect arguments are inside the buffer", [](Objects& o) { o.bindForDispatch(); },
         [](Objects& o) { o.list->dispatchIndirect(*o.indirect, 4); }, E::Error,
         text("dispatchIndirect arguments: 12 bytes at offset 4 exceed buffer 'indirect' (12 bytes)")},
        {"indirect draws happen inside passes", [](Objects& o) { o.makeCompute(); },
         [](Objects& o) { o.list->drawIndirect(*o.indirect); }, E::Error,
         text("drawIndirect: not inside a pass; call beginPass() first")},
        {"indirect draws' arguments are inside the buffer",
         [](Objects& o) {
             o.makeCompute();
             o.bindForDraw();
         },
         [](Objects& o) { o.list->drawIndirect(*o.indirect); }, E::Error,
         text("drawIndirect arguments: 16 bytes at offset 0 exceed buffer 'indirect' (12 bytes)")},
        {"indirect indexed draws read indices from offset 0",
         [](Objects& o) {
             o.makeCompute();
             o.localBuffer =
                 o.device.createBuffer({.size = 20, .usage = rhi::BufferUsage::Indirect, .debugName = "arguments"});
             o.bindForDraw();
             o.list->bindIndexBuffer(*o.indices, rhi::IndexType::UInt16, 2);
         },
         [](Objects& o) { o.list->drawIndexedIndirect(*o.localBuffer); }, E::Error,
         text("drawIndexedIndirect: the index buffer is bound at offset 2; indirect indexed draws need offset 0 "
              "(start with the arguments' firstIndex)")},
        {"count buffers need BufferUsage::Indirect",
         [](Objects& o) {
             o.makeCompute();
             o.bindForDraw();
         },
         [](Objects& o) { o.list->drawIndirectCount(*o.indirect, 0, *o.storage, 0, 0); }, E::Error,
         text("drawIndirectCount count: buffer 'storage' lacks BufferUsage::Indirect")},
        {"count draws' commands are inside the buffer",
         [](Objects& o) {
             o.makeCompute();
             o.bindForDraw();
         },
         [](Objects& o) { o.list->drawIndirectCount(*o.indirect, 0, *o.indirect, 0, 1); }, E::Error,
         text("drawIndirectCount arguments: 16 bytes at offset 0 exceed buffer 'indirect' (12 bytes)")},
        {"count offsets are multiples of 4",
         [](Objects& o) {
             o.makeCompute();
             o.bindForDraw();
         },
         [](Objects& o) { o.list->drawIndirectCount(*o.indirect, 0, *o.indirect, 2, 0); }, E::Error,
         text("drawIndirectCount count: offset 2 is not a multiple of 4")},
        {"counts are inside their buffer",
         [](Objects& o) {
             o.makeCompute();
             o.bindForDraw();
         },
         [](Objects& o) { o.list->drawIndexedIndirectCount(*o.indirect, 0, *o.indirect, 12, 0); }, E::Error,
         text("drawIndexedIndirectCount count: 4 bytes at offset 12 exceed buffer 'indirect' (12 bytes)")},
        // Explicit barriers and the uses they declare.
        {"barriers are recorded outside passes", [](Objects& o) { o.beginPass(); },
         [](Objects& o) { o.barriers({rhi::ResourceBarrier::of(*o.image, S::Undefined, S::ShaderRead)}); }, E::Error,
         text("resourceBarriers: not allowed inside a pass; call endPass() first")},
        {"a barrier names one resource", nothing,
         [](Objects& o) { o.barriers({rhi::ResourceBarrier{.after = S::ShaderRead}}); }, E::Error,
         text("resourceBarriers: a barrier names no resource; name one texture or one buffer")},
        {"a barrier goes to a defined state", nothing,
         [](Objects& o) { o.barriers({rhi::ResourceBarrier::of(*o.image, S::Undefined, S::Undefined)}); }, E::Error,
         text("resourceBarriers: texture 'image' goes to state Undefined; name the state it is used in next")},
        {"a barrier's state needs the resource's usage", nothing,
         [](Objects& o) { o.barriers({rhi::ResourceBarrier::of(*o.image, S::Undefined, S::RenderTarget)}); }, E::Error,
         text("resourceBarriers: texture 'image' cannot be in state RenderTarget, which needs "
              "TextureUsage::RenderTarget")},
        {"a barrier leaves the state the list last declared",
         [](Objects& o) { o.barriers({rhi::ResourceBarrier::of(*o.image, S::Undefined, S::ShaderRead)}); },
         [](Objects& o) { o.barriers({rhi::ResourceBarrier::of(*o.image, S::Undefined, S::ShaderRead)}); }, E::Error,
         text("resourceBarriers: texture 'image' leaves state Undefined, but the list last declared ShaderRead")},
        {"a resource has one barrier per call", nothing,
         [](Objects& o) {
             o.barriers({rhi::ResourceBarrier::of(*o.image, S::Undefined, S::ShaderRead),
                         rhi::ResourceBarrier::of(*o.image, S::Undefined, S::ShaderRead)});
         },
         E::Error, text("resourceBarriers: texture 'image' has two barriers in one call; merge their states")},
        {"draws use only what the pass's barriers declared",
         [](Objects& o) {
             o.uniforms->writeObject(TransformUniforms{});
             o.barriers({rhi::ResourceBarrier::of(*o.image, S::Undefined, S::ShaderRead)});
             o.list->pushLabel("shading");
             o.barriers({});
             o.bindForDraw();
         },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: pass 'shading' uses texture 'image' as ShaderRead (binding 1, 'image'), but its "
              "resourceBarriers do not declare it")},
        {"copies use their resources as the barriers declared",
         [](Objects& o) { o.barriers({rhi::ResourceBarrier::of(*o.color, S::Undefined, S::ShaderRead)}); },
         [](Objects& o) { o.list->copyTextureToBuffer(*o.color, 0, 0, *o.readback, 0); }, E::Error,
         text("copyTextureToBuffer: uses texture 'color' as CopySource (source), but the last resourceBarriers "
              "declare it ShaderRead only")},
        // Binding sets.
        {"binding set layouts list each binding once", nothing,
         [](Objects& o) {
             o.device.createBindingSetLayout(
                 {.items = {{1, rhi::BindingKind::SampledTexture}, {1, rhi::BindingKind::UniformBuffer}},
                  .debugName = "bad"});
         },
         E::Error, text("binding set layout 'bad': binding 1 is listed twice")},
        {"binding sets fill every binding of their layout", [](Objects& o) { o.makeLayout(); },
         [](Objects& o) {
             o.device.createBindingSet({.layout = o.layout.get(),
                                        .items = {rhi::BindingSetItem::uniformBuffer(0, *o.uniforms, 0, 64)},
                                        .debugName = "bad"});
         },
         E::Error, text("binding set 'bad': layout 'fixture' binding 1 (texture and sampler) has no item")},
        {"binding set items are of their layout's kind", [](Objects& o) { o.makeLayout(); },
         [](Objects& o) {
             o.device.createBindingSet({.layout = o.layout.get(),
                                        .items = {rhi::BindingSetItem::sampledTexture(0, *o.image, *o.sampler)},
                                        .debugName = "bad"});
         },
         E::Error,
         text("binding set 'bad': binding 0 holds a texture and sampler, but layout 'fixture' declares a uniform "
              "buffer there")},
        {"binding set items are in their layout", [](Objects& o) { o.makeLayout(); },
         [](Objects& o) {
             o.device.createBindingSet({.layout = o.layout.get(),
                                        .items = {rhi::BindingSetItem::uniformBuffer(2, *o.uniforms, 0, 64)},
                                        .debugName = "bad"});
         },
         E::Error, text("binding set 'bad': binding 2 is not in layout 'fixture'")},
        {"binding set buffers have their kind's usage", [](Objects& o) { o.makeLayout(); },
         [](Objects& o) {
             o.device.createBindingSet({.layout = o.layout.get(),
                                        .items = {rhi::BindingSetItem::uniformBuffer(0, *o.vertices, 0, 36),
                                                  rhi::BindingSetItem::sampledTexture(1, *o.image, *o.sampler)},
                                        .debugName = "bad"});
         },
         E::Error, text("binding set 'bad' binding 0: buffer 'vertices' lacks BufferUsage::Uniform")},
        {"binding set textures are Sampled", [](Objects& o) { o.makeLayout(); },
         [](Objects& o) {
             o.device.createBindingSet({.layout = o.layout.get(),
                                        .items = {rhi::BindingSetItem::uniformBuffer(0, *o.uniforms, 0, 64),
                                                  rhi::BindingSetItem::sampledTexture(1, *o.small, *o.sampler)},
                                        .debugName = "bad"});
         },
         E::Error, text("binding set 'bad' binding 1: texture 'small' lacks TextureUsage::Sampled")},
        {"binding set storage images are Storage", nothing,
         [](Objects& o) {
             auto layout = o.device.createBindingSetLayout(
                 {.items = {{0, rhi::BindingKind::StorageTexture}}, .debugName = "images"});
             o.device.createBindingSet({.layout = layout.get(),
                                        .items = {rhi::BindingSetItem::storageTexture(0, *o.image)},
                                        .debugName = "bad"});
         },
         E::Error, text("binding set 'bad' binding 0: texture 'image' lacks TextureUsage::Storage")},
        {"a binding set's layout matches the pipeline's",
         [](Objects& o) {
             o.uniforms->writeObject(TransformUniforms{});
             auto layout = o.device.createBindingSetLayout(
                 {.items = {{0, rhi::BindingKind::SampledTexture}}, .debugName = "swapped"});
             o.set = o.device.createBindingSet({.layout = layout.get(),
                                                .items = {rhi::BindingSetItem::sampledTexture(0, *o.image, *o.sampler)},
                                                .debugName = "swapped"});
             o.bindForDraw();
             o.list->bindBindingSet(*o.set);
         },
         [](Objects& o) { o.list->draw(3); }, E::Error,
         text("draw: binding set 'swapped' (layout 'swapped') holds a texture and sampler at binding 0, but pipeline "
              "'bad' declares a uniform buffer there ('Transform'): the set's layout differs from the pipeline's")},
        {"pipelines list binding set layouts of their bindings' kinds",
         [](Objects& o) {
             o.layout = o.device.createBindingSetLayout(
                 {.items = {{0, rhi::BindingKind::SampledTexture}}, .debugName = "swapped"});
         },
         [](Objects& o) {
             rhi::PipelineDesc d = o.pipelineDesc();
             d.bindingSetLayouts = {o.layout.get()};
             o.device.createPipeline(d);
         },
         E::Error,
         text("pipeline 'bad': binding 0 ('Transform') is a uniform buffer in the shaders, but binding set layout "
              "'swapped' holds a texture and sampler there")},
        {"pipelines list each binding in one binding set layout at most", [](Objects& o) { o.makeLayout(); },
         [](Objects& o) {
             auto other = o.device.createBindingSetLayout(
                 {.items = {{1, rhi::BindingKind::SampledTexture}}, .debugName = "texture"});
             rhi::PipelineDesc d = o.pipelineDesc();
             d.bindingSetLayouts = {o.layout.get(), other.get()};
             o.device.createPipeline(d);
         },
         E::Error, text("pipeline 'bad': binding 1 is in binding set layouts 'fixture' and 'texture'")},
        {"compute pipelines list no null binding set layout", nothing,
         [](Objects& o) {
             o.makeCompute();
             o.device.createComputePipeline(
                 {.compute = o.computeShader.get(), .bindingSetLayouts = {nullptr}, .debugName = "bad"});
         },
         E::Error, text("pipeline 'bad': bindingSetLayouts[0] is null")},
        // Ownership and lifetime.
        {"lists are submitted to the device that created them", nothing,
         [](Objects& o) {
             auto other = createValidatedDevice(configuration());
             auto foreign = other->createCommandList();
             o.device.submit(*foreign);
         },
         E::Error, text("submit: the command list was not created by this device")},
        {"lists are not used after their device", nothing,
         [](Objects&) {
             auto other = createValidatedDevice(configuration());
             auto orphan = other->createCommandList();
             other.reset();
             orphan->endPass();
         },
         E::Error, text("endPass: the device that created this command list was destroyed")},
    };
    return table;
}

std::string describeException(const std::exception& e)
{
    return fmt::format("{} \"{}\"",
                       dynamic_cast<const rhi::UnsupportedError*>(&e) ? "UnsupportedError"
                       : dynamic_cast<const rhi::Error*>(&e)          ? "Error"
                                                                      : typeid(e).name(),
                       e.what());
}

using MisuseTest = GpuTest;

TEST_F(MisuseTest, TheTableHasAtLeastThirtyRules) { EXPECT_GE(rules().size(), 30u); }

// The positive control: the fixture's draw is valid, so no rule fires for it and it runs.
TEST_F(MisuseTest, TheFixturesDrawBreaksNoRule)
{
    Objects o(*device);
    o.uniforms->writeObject(TransformUniforms{});
    o.bindForDraw();
    o.list->draw(3);
    o.list->endPass();
    EXPECT_NO_THROW(device->submit(*o.list));
}

// The positive control of the instance-range rows: the instances that fit the per-instance buffer, and no more, are
// drawn by either draw without an error.
TEST_F(MisuseTest, InstancesThatFitTheirBufferBreakNoRule)
{
    Objects o(*device);
    o.uniforms->writeObject(TransformUniforms{});
    o.indices->writeObject(std::array<std::uint16_t, 3>{0, 1, 2});
    o.bindForInstancedDraw();
    EXPECT_NO_THROW(o.list->draw(3, 3));
    EXPECT_NO_THROW(o.list->drawIndexed(3, 2, 0, 0, 1));
    o.list->endPass();
    EXPECT_NO_THROW(device->submit(*o.list));
}

// Size 0 is no misuse: an empty buffer (a scene with nothing to draw) is created, written with nothing and bound
// where no byte is read, on every backend alike.
TEST_F(MisuseTest, AnEmptyBufferIsValid)
{
    Objects o(*device);
    auto empty = device->createBuffer({.size = 0, .usage = rhi::BufferUsage::Vertex, .debugName = "empty"});
    EXPECT_EQ(empty->desc().size, 0u);
    empty->write(0, {});
    o.bindForDraw("vertex");
    o.list->bindVertexBuffer(0, *empty);
    o.list->draw(0);
    o.list->endPass();
    EXPECT_NO_THROW(device->submit(*o.list));
}

TEST_F(MisuseTest, EveryRuleRaisesItsErrorAtTheBreakingCall)
{
    for (const Rule& rule : rules()) {
        SCOPED_TRACE(rule.rule);
        Objects o(*device);
        try {
            rule.setup(o);
        } catch (const std::exception& e) {
            ADD_FAILURE() << "the setup threw " << describeException(e);
            continue;
        }
        const std::string expected = rule.message(device->capabilities());
        try {
            rule.breaking(o);
            ADD_FAILURE() << "the breaking call was accepted; expected \"" << expected << "\"";
        } catch (const rhi::UnsupportedError& e) {
            EXPECT_EQ(rule.raises, Raises::Unsupported) << describeException(e);
            EXPECT_EQ(std::string(e.what()), expected);
        } catch (const rhi::Error& e) {
            EXPECT_EQ(rule.raises, Raises::Error) << describeException(e);
            EXPECT_EQ(std::string(e.what()), expected);
        }
    }
}

} // namespace
} // namespace penumbra::testing
