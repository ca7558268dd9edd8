#pragma once

#include "penumbra/rhi/BindingSet.hpp"
#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Configuration.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/LiveObjects.hpp"
#include "penumbra/rhi/Pipeline.hpp"
#include "penumbra/rhi/Resources.hpp"
#include "penumbra/rhi/Shader.hpp"
#include "penumbra/rhi/Window.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace penumbra::rhi {

// What the driver offers for one format, as it reports it.
struct FormatSupport {
    bool sampled = false; // created with TextureUsage::Sampled (and, like every texture, uploaded and copied)
    bool linearFilter = false; // sampled with a linear mag, min or mip filter
    bool renderTarget = false; // a colour or depth attachment, by format
    // Sample counts of a render target of this format (TextureDesc::samples), one bit each with the count's value
    // (1 | 2 | 4 | 8, Vulkan's VkSampleCountFlags): 1 where renderTarget, more as the driver reports them (Vulkan:
    // the image format's sampleCounts within framebufferColorSampleCounts or framebufferDepthSampleCounts; GL:
    // GL_SAMPLES of GL_TEXTURE_2D_MULTISAMPLE, ARB_internalformat_query2). Counts above 8 are not offered.
    std::uint32_t sampleCounts = 0;
    // A storage image (TextureUsage::Storage, imageLoad and imageStore) of this format: Vulkan's
    // VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT; GL's GL_SHADER_IMAGE_LOAD and _STORE (ARB_internalformat_query2).
    bool storage = false;
};

// The counts 1, 2, 4 and 8 that a sampleCounts mask holds, ascending ("1, 4").
std::string sampleCountList(std::uint32_t sampleCounts);

// What the driver really offers; nothing here is faked or emulated.
struct Capabilities {
    std::string api; // "Vulkan 1.3.230", "OpenGL 4.5 (Core Profile) Mesa 22.3.6"
    std::string device; // "llvmpipe (LLVM 15.0.6, 256 bits)"
    bool depthClamp = false;
    bool depthBiasClamp = false;
    bool timestamps = false;
    std::uint32_t uniformBufferOffsetAlignment = 256;
    // Largest range bindUniformBuffer takes (Vulkan's maxUniformBufferRange, GL_MAX_UNIFORM_BLOCK_SIZE).
    std::uint32_t maxUniformBufferRange = 16384;
    std::uint32_t maxTextureSize = 0;
    std::uint32_t maxTextureLayers = 0;
    // Cube textures (TextureDesc::cube) are cube-map arrays: Vulkan's imageCubeArray feature, core in GL 4.0.
    bool cubeArrays = false;
    std::uint32_t maxCubeSize = 0;
    // Highest SamplerDesc::maxAnisotropy: Vulkan's samplerAnisotropy feature and limit, GL 4.6 or
    // ARB/EXT_texture_filter_anisotropic; 1 where the device has no anisotropic filtering.
    float maxSamplerAnisotropy = 1.0f;
    // Bytes of the device's largest memory heap (Vulkan's largest DEVICE_LOCAL heap; for OpenGL's software
    // renderers, which keep textures in system memory, the machine's physical memory); 0 where the API does not
    // say. A buffer or texture larger than this is refused before the API is asked (Device::createTexture).
    std::uint64_t deviceMemoryBytes = 0;
    // Whether a lost device is reported (rhi::DeviceLostError from submit): always on Vulkan (VK_ERROR_DEVICE_LOST);
    // on OpenGL where the context was made with the lose-context-on-reset strategy (EGL_EXT_create_context_robustness,
    // GLFW's GLFW_LOSE_CONTEXT_ON_RESET), without which a reset leaves the context's behaviour undefined.
    bool deviceLossReported = false;
    // Compute (Vulkan 1.3 section 48 limits; GL 4.5 Table 23.64): invocations per workgroup along x, y, z and in
    // all (maxComputeWorkGroupSize, maxComputeWorkGroupInvocations), workgroups per dispatch along x, y, z
    // (maxComputeWorkGroupCount), and bytes of `shared` variables (maxComputeSharedMemorySize).
    std::array<std::uint32_t, 3> maxWorkgroupSize{};
    std::uint32_t maxWorkgroupInvocations = 0;
    std::array<std::uint32_t, 3> maxWorkgroupCount{};
    std::uint32_t maxComputeSharedMemory = 0;
    // Storage blocks: bindStorageBuffer's offset alignment and largest range (minStorageBufferOffsetAlignment and
    // maxStorageBufferRange; GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT and GL_MAX_SHADER_STORAGE_BLOCK_SIZE).
    std::uint32_t storageBufferOffsetAlignment = 256;
    std::uint64_t maxStorageBufferRange = 0;
    // Draw counts read on the GPU (CommandList::drawIndirectCount): Vulkan 1.2's drawIndirectCount feature or
    // VK_KHR_draw_indirect_count; GL 4.6 or ARB_indirect_parameters; false with DeviceDesc::nativeDrawIndirectCount
    // off. Where false the RHI emulates the count, with the same picture and a cost docs/compute.md describes.
    bool drawIndirectCount = false;
    // Compiled pipelines the driver hands back for the pipeline cache (DeviceDesc::pipelineCache): always on Vulkan
    // (VkPipelineCache); on OpenGL where GL_NUM_PROGRAM_BINARY_FORMATS > 0 (GL 4.6 section 7.5 "Program Binaries"),
    // which Mesa reports only while its own shader disk cache is on. Without it the cache keeps SPIR-V alone.
    bool pipelineBinaries = false;
    // Indexed by Format. Linear filtering of depth formats is hardware 2x2 PCF with a comparison sampler;
    // lavapipe offers it for none (conventions note, section 4).
    std::array<FormatSupport, formatCount> formats{};

    // What the driver offers for one format.
    const FormatSupport& format(Format f) const { return formats[static_cast<std::size_t>(f)]; }
    // Whether the driver can filter the format linearly (lavapipe: no depth format).
    bool supportsLinearFilter(Format f) const { return format(f).linearFilter; }
    // The sample counts offered for every one of `targets` (their sampleCounts masks intersected): what a
    // framebuffer of those formats can use.
    std::uint32_t sampleCounts(std::span<const Format> targets) const;
};

// Threading: a Device and every object it created (buffers, textures, command lists, ...) are used only from the
// thread that created the device, one call at a time (an OpenGL context is current on one thread, EGL 1.5 section
// 3.7.3 "eglMakeCurrent"). Each device owns its own API context, so devices share no state with one another.
// The one exception is recording: command lists of one device may be recorded on several threads at once, one list
// per thread, and may all read the same pipelines, buffers, textures, samplers and framebuffers. Creating, writing
// (Buffer::write, writeTexture), reading back and destroying objects, and submit, stay on the device's thread, and a
// list is submitted after its recording thread is done with it (joined, or handed back through a mutex). Lists run
// in the order they are submitted, whatever order they were recorded in. Vulkan records into a command pool and
// descriptor pools of the list's own (pools are externally synchronized, Vulkan 1.3 section 3.6 "Threading
// Behavior"); OpenGL records into a list of the list's own and makes its GL calls at submit, on the device's thread.
class Device : private LiveObject<ObjectKind::Device> {
public:
    virtual ~Device() = default;

    // The description the device was created with.
    virtual const DeviceDesc& desc() const = 0;
    // The depth range and reversed-Z of this device as numbers: projections, clear depth, compare ops.
    virtual const Conventions& conventions() const = 0;
    // What the driver offers: formats, sample counts, limits, memory.
    virtual const Capabilities& capabilities() const = 0;

    // Out of memory is an Error naming the resource (its debugName) and its size: a request larger than
    // Capabilities::deviceMemoryBytes before the API is asked, an allocation the driver refuses after. Nothing is
    // created then and the device stays usable.
    virtual std::unique_ptr<Buffer> createBuffer(const BufferDesc& desc) = 0;
    // A texture as described; the validation layer names the field of a description it refuses.
    virtual std::unique_ptr<Texture> createTexture(const TextureDesc& desc) = 0;
    // Uploads one whole mip level of one layer: tightly packed rows of mipExtent(width, level) texels, row 0
    // (the top of the picture) first, texels laid out as copyTextureToBuffer gives them (D24S8: 32-bit words,
    // depth in the low 24 bits).
    virtual void writeTexture(Texture& texture, std::uint32_t layer, std::uint32_t level,
                              std::span<const std::byte> data) = 0;
    // A sampler as described; anisotropy above Capabilities::maxSamplerAnisotropy is refused.
    virtual std::unique_ptr<Sampler> createSampler(const SamplerDesc& desc) = 0;
    // Compiles with glslang (errors name the source and line) and creates the backend's module.
    virtual std::unique_ptr<Shader> createShader(const ShaderSource& source) = 0;
    // Links the shaders and fixed state; bindings and uniform layouts are checked against reflection.
    virtual std::unique_ptr<Pipeline> createPipeline(const PipelineDesc& desc) = 0;
    // A compute pipeline; its workgroup size and shared memory are checked against the limits in Capabilities,
    // its uniform and storage layouts against reflection.
    virtual std::unique_ptr<ComputePipeline> createComputePipeline(const ComputePipelineDesc& desc) = 0;
    // The binding numbers and kinds binding sets of one shape hold; each number listed once.
    virtual std::unique_ptr<BindingSetLayout> createBindingSetLayout(const BindingSetLayoutDesc& desc) = 0;
    // A set of resources for CommandList::bindBindingSet: one item per binding of the layout, each checked as its
    // single bind call checks it.
    virtual std::unique_ptr<BindingSet> createBindingSet(const BindingSetDesc& desc) = 0;
    // Colour and depth attachments of one size and sample count, for CommandList::beginPass.
    virtual std::unique_ptr<Framebuffer> createFramebuffer(const FramebufferDesc& desc) = 0;
    // `count` GPU timestamps for CommandList::writeTimestamp, read with readTimestamps.
    virtual std::unique_ptr<TimestampQueries> createTimestampQueries(std::uint32_t count) = 0;
    // An empty command list of this device.
    virtual std::unique_ptr<CommandList> createCommandList() = 0;
    // The swapchain of DeviceDesc::window; throws Error when the device was created without one,
    // or when the driver cannot present to it. At most one per device.
    virtual std::unique_ptr<Swapchain> createSwapchain() = 0;

    // Runs everything the list recorded and waits until the GPU has finished.
    virtual void submit(CommandList& commands) = 0;

    // Nanoseconds, one per query, from a submitted list's writeTimestamp calls.
    virtual std::vector<double> readTimestamps(const TimestampQueries& queries) = 0;

    // Every validation-layer or debug-output message since creation or the last clear.
    virtual std::vector<std::string> debugMessages() const = 0;
    // Forgets the messages debugMessages() returned.
    virtual void clearDebugMessages() = 0;
};

} // namespace penumbra::rhi
