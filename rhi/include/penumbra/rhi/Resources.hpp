#pragma once

#include "penumbra/rhi/Flags.hpp"
#include "penumbra/rhi/Format.hpp"
#include "penumbra/rhi/LiveObjects.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace penumbra::rhi {

// Descriptors are plain aggregates: every field has a usable default, so
// `device.createBuffer({.size = 256, .usage = BufferUsage::Uniform})` is a complete request.

enum class BufferUsage : std::uint8_t {
    None = 0,
    Vertex = 1 << 0,
    Index = 1 << 1,
    Uniform = 1 << 2,
    Readback = 1 << 3, // destination of texture and buffer copies, read on the CPU
    Storage = 1 << 4, // a storage block (`buffer`) read or written by shaders: bindStorageBuffer
    Indirect = 1 << 5, // arguments of dispatchIndirect, drawIndirect and drawIndexedIndirect
};
constexpr bool enableFlags(BufferUsage) { return true; }

// A size of 0 is a valid empty buffer (a scene with nothing to draw): it can be bound where no byte is read.
// Binding checks the usage: Vertex for bindVertexBuffer, Index for bindIndexBuffer, Uniform for
// bindUniformBuffer, Storage for bindStorageBuffer, Indirect for the indirect commands' arguments.
struct BufferDesc {
    std::uint64_t size = 0;
    BufferUsage usage = BufferUsage::None;
    std::string debugName;
};

// Buffers live in CPU-visible memory. The GPU reads them when a command list is submitted,
// so a write between recording and submitting is seen by every draw of that submission.
class Buffer : private LiveObject<ObjectKind::Buffer> {
public:
    virtual ~Buffer() = default;
    // The description the buffer was created with.
    virtual const BufferDesc& desc() const = 0;
    // Copies bytes into the buffer at `offset`; seen by every draw of the next submission.
    virtual void write(std::uint64_t offset, std::span<const std::byte> data) = 0;
    // Copies bytes out of the buffer at `offset` (after a submission: what the GPU wrote).
    virtual void read(std::uint64_t offset, std::span<std::byte> data) const = 0;

    template <typename T>
    // Writes one trivially copyable value at `offset`.
    void writeObject(const T& value, std::uint64_t offset = 0)
    {
        write(offset, std::as_bytes(std::span(&value, 1)));
    }
};

enum class TextureUsage : std::uint8_t {
    None = 0,
    Sampled = 1 << 0,
    RenderTarget = 1 << 1, // colour or depth attachment, by format
    // Read and written by shaders with imageLoad/imageStore (bindStorageTexture): a single-layer 2D texture of
    // a format with FormatSupport::storage.
    Storage = 1 << 2,
};
constexpr bool enableFlags(TextureUsage) { return true; }

// Levels of the full mip chain of a width x height texture, down to 1 x 1: floor(log2(max)) + 1.
constexpr std::uint32_t fullMipChain(std::uint32_t width, std::uint32_t height)
{
    return std::uint32_t(std::bit_width(std::max({width, height, 1u})));
}

// Width or height of mip level `level`: halved per level, rounded down, at least 1 (Vulkan 1.3 section 12.3,
// GL 4.5 section 8.14.3).
constexpr std::uint32_t mipExtent(std::uint32_t size, std::uint32_t level)
{
    return level >= 32 ? 1u : std::max(size >> level, 1u);
}

// Every texture can be copied from and to and uploaded with Device::writeTexture, level by level.
struct TextureDesc {
    std::uint32_t width = 1;
    std::uint32_t height = 1;
    std::uint32_t layers = 1;
    bool array = false; // a 2D array (sampler2DArray) even when layers == 1
    // A cube-map array (samplerCubeArray / samplerCubeArrayShadow) on every backend, even for one
    // cube, so one GLSL type serves; `array` is then ignored. Needs width == height, layers a
    // positive multiple of 6 and Capabilities::cubeArrays. Layer cubeLayer(cube, face) holds one
    // face (CubeMap.hpp: face order +X, -X, +Y, -Y, +Z, -Z, and how to render each face).
    bool cube = false;
    // 1..fullMipChain(width, height). Level 0 is the one rendered to; every level is uploaded, copied and
    // read back on its own (generateMipChain in MipChain.hpp fills a chain on the CPU).
    std::uint32_t mipLevels = 1;
    Format format = Format::RGBA8;
    TextureUsage usage = TextureUsage::Sampled;
    // Samples per texel: 1, or a multisampled render target of 2, 4 or 8 samples where the device offers that count
    // for the format (FormatSupport::sampleCounts). A multisampled texture is a RenderTarget and nothing else: one
    // layer, one mip level, not sampled, uploaded, copied or read back; CommandList::resolveTexture averages it into
    // a single-sampled texture.
    std::uint32_t samples = 1;
    std::string debugName;
};

// A texture of the device that created it (TextureDesc says its size, format, layers, levels, samples).
class Texture : private LiveObject<ObjectKind::Texture> {
public:
    virtual ~Texture() = default;
    // The description the texture was created with.
    virtual const TextureDesc& desc() const = 0;
};

enum class Filter : std::uint8_t { Nearest, Linear };
// Between mip levels: None samples level 0 only (GL's GL_NEAREST and GL_LINEAR minification), Nearest picks
// the nearest level, Linear blends the two nearest (trilinear with linear min and mag filters).
enum class MipFilter : std::uint8_t { None, Nearest, Linear };
enum class AddressMode : std::uint8_t { ClampToEdge, Repeat, MirroredRepeat };

// With compare set this is a shadow sampler for sampler2DShadow, sampler2DArrayShadow or
// samplerCubeArrayShadow; its compare op is Conventions::shadowCompareOp() (lit where the
// receiver is nearer or as near).
// Linear filtering (any of the three filters) is refused where the driver cannot filter the texture's format
// (Capabilities::supportsLinearFilter) when the pair is bound. Cube textures ignore the address modes.
struct SamplerDesc {
    Filter magFilter = Filter::Linear;
    Filter minFilter = Filter::Linear;
    MipFilter mipFilter = MipFilter::None;
    AddressMode addressU = AddressMode::ClampToEdge;
    AddressMode addressV = AddressMode::ClampToEdge;
    // The level-of-detail clamp, 0 <= minLod <= maxLod (1000: no clamp); ignored with MipFilter::None.
    float minLod = 0.0f;
    float maxLod = 1000.0f;
    // 1 (off) up to Capabilities::maxSamplerAnisotropy; more is refused.
    float maxAnisotropy = 1.0f;
    bool compare = false;
    std::string debugName;
};

// How a texture is filtered and addressed when read (SamplerDesc).
class Sampler : private LiveObject<ObjectKind::Sampler> {
public:
    virtual ~Sampler() = default;
    // The description the sampler was created with.
    virtual const SamplerDesc& desc() const = 0;
};

// One colour or depth attachment: a texture layer (of a cube texture: one face, cubeLayer(cube, face)).
struct Attachment {
    const Texture* texture = nullptr;
    std::uint32_t layer = 0;
};

// The attachments share one size and one sample count (TextureDesc::samples).
struct FramebufferDesc {
    std::span<const Attachment> colors;
    Attachment depth;
    std::string debugName;
};

// The formats of a framebuffer's attachments, in order, and their sample count; a pipeline draws into a pass whose
// framebuffer has exactly its PipelineDesc::colorTargets formats, depthFormat and samples.
struct AttachmentFormats {
    std::vector<Format> colors;
    std::optional<Format> depth;
    std::uint32_t samples = 1;

    // Equal formats, in order, and sample count.
    bool operator==(const AttachmentFormats&) const = default;
};

AttachmentFormats attachmentFormats(const FramebufferDesc& desc);

// The attachments a pass draws into (FramebufferDesc).
class Framebuffer : private LiveObject<ObjectKind::Framebuffer> {
public:
    virtual ~Framebuffer() = default;
    // Width of every attachment, in pixels.
    virtual std::uint32_t width() const = 0;
    // Height of every attachment, in pixels.
    virtual std::uint32_t height() const = 0;
    // The attachments' formats and sample count, which a pipeline drawing here must match.
    virtual const AttachmentFormats& formats() const = 0;
};

// GPU timestamps written by CommandList::writeTimestamp and read by Device::readTimestamps.
class TimestampQueries : private LiveObject<ObjectKind::TimestampQueries> {
public:
    virtual ~TimestampQueries() = default;
    // How many timestamps the set holds.
    virtual std::uint32_t count() const = 0;
};

} // namespace penumbra::rhi
