// Descriptor, range and usage rules of buffers, textures, samplers, framebuffers and queries.

#include "Rules.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/Error.hpp"

#include <cstring>
#include <fmt/format.h>

namespace penumbra::rhi {
namespace {

bool filtersLinearly(const SamplerDesc& desc)
{
    return desc.magFilter == Filter::Linear || desc.minFilter == Filter::Linear || desc.mipFilter == MipFilter::Linear;
}

// What a multisampled texture may be (TextureDesc::samples): a render target of one layer and level, as Vulkan's
// vkCmdResolveImage and GL's glBlitFramebuffer take it and nothing samples, uploads or reads it back.
void checkMultisampledTexture(const Capabilities& caps, const TextureDesc& desc)
{
    if (desc.samples > 1 && (caps.format(desc.format).sampleCounts & desc.samples) == 0)
        throw UnsupportedError(
            fmt::format("texture '{}': {} offers {} samples for {} render targets, not {}", desc.debugName, caps.device,
                        sampleCountList(caps.format(desc.format).sampleCounts), formatName(desc.format), desc.samples));
    if (desc.usage != TextureUsage::RenderTarget)
        throw Error(fmt::format("texture '{}': a multisampled texture ({} samples) is a RenderTarget and not Sampled "
                                "(resolveTexture makes a texture to sample)",
                                desc.debugName, desc.samples));
    if (desc.layers != 1 || desc.mipLevels != 1 || desc.cube || desc.array)
        throw Error(fmt::format("texture '{}': a multisampled texture ({} samples) has one layer and one mip level, "
                                "not {} layers and {} levels{}",
                                desc.debugName, desc.samples, desc.layers, desc.mipLevels,
                                desc.cube ? " of a cube" : (desc.array ? " of an array" : "")));
}

void refuseMultisampled(std::string_view what, const TextureDesc& desc)
{
    if (desc.samples > 1)
        throw Error(fmt::format("{}: texture '{}' is multisampled ({} samples); resolveTexture gives a single-sampled "
                                "texture",
                                what, desc.debugName, desc.samples));
}

} // namespace

void checkTextureBinding(std::string_view what, const Capabilities& caps, const Texture& texture,
                         const Sampler& sampler)
{
    const TextureDesc& desc = texture.desc();
    if (!hasFlag(desc.usage, TextureUsage::Sampled))
        throw Error(fmt::format("{}: texture '{}' lacks TextureUsage::Sampled", what, desc.debugName));
    const Format format = desc.format;
    if (filtersLinearly(sampler.desc()) && !caps.supportsLinearFilter(format))
        throw UnsupportedError(
            fmt::format("{}: texture '{}' ({}) with linear sampler '{}': this driver ({}) cannot filter {} linearly; "
                        "use a nearest sampler and filter in the shader",
                        what, desc.debugName, formatName(format), sampler.desc().debugName, caps.device,
                        formatName(format)));
}

void checkTextureDesc(const Capabilities& caps, const TextureDesc& desc)
{
    if (desc.width == 0 || desc.height == 0 || desc.layers == 0 || desc.width > caps.maxTextureSize ||
        desc.height > caps.maxTextureSize || desc.layers > caps.maxTextureLayers)
        throw Error(fmt::format("texture '{}': {}x{} with {} layers is outside 1..{} texels and 1..{} layers",
                                desc.debugName, desc.width, desc.height, desc.layers, caps.maxTextureSize,
                                caps.maxTextureLayers));
    const std::uint32_t fullChain = fullMipChain(desc.width, desc.height);
    if (desc.mipLevels == 0 || desc.mipLevels > fullChain)
        throw Error(fmt::format("texture '{}': mipLevels {} is outside 1..{} (the full chain of {}x{})", desc.debugName,
                                desc.mipLevels, fullChain, desc.width, desc.height));
    const FormatSupport& support = caps.format(desc.format);
    if (hasFlag(desc.usage, TextureUsage::Sampled) && !support.sampled)
        throw UnsupportedError(
            fmt::format("texture '{}': {} cannot sample {}", desc.debugName, caps.device, formatName(desc.format)));
    if (hasFlag(desc.usage, TextureUsage::RenderTarget) && !support.renderTarget)
        throw UnsupportedError(
            fmt::format("texture '{}': {} cannot render to {}", desc.debugName, caps.device, formatName(desc.format)));
    if (hasFlag(desc.usage, TextureUsage::Storage) && !support.storage)
        throw UnsupportedError(fmt::format("texture '{}': {} cannot use {} as a storage image", desc.debugName,
                                           caps.device, formatName(desc.format)));
    // One image2D view serves every backend: no arrays, cubes or samples (a storage image is bound by mip level).
    if (hasFlag(desc.usage, TextureUsage::Storage) && (desc.layers != 1 || desc.array || desc.cube))
        throw Error(fmt::format("texture '{}': a Storage texture is one 2D layer, not {} layers{}", desc.debugName,
                                desc.layers, desc.cube ? " of a cube" : (desc.array ? " of an array" : "")));
    if (desc.samples != 1 && desc.samples != 2 && desc.samples != 4 && desc.samples != 8)
        throw Error(fmt::format("texture '{}': samples {} is not 1, 2, 4 or 8", desc.debugName, desc.samples));
    if (desc.samples > 1)
        checkMultisampledTexture(caps, desc);
    if (!desc.cube)
        return;
    if (!caps.cubeArrays)
        throw UnsupportedError(fmt::format("texture '{}': cube textures are cube-map arrays, which {} does not offer",
                                           desc.debugName, caps.device));
    if (desc.layers % 6 != 0)
        throw Error(fmt::format("texture '{}': a cube texture needs a multiple of 6 layers (one per face), not {}",
                                desc.debugName, desc.layers));
    if (desc.width != desc.height)
        throw Error(fmt::format("texture '{}': a cube texture needs square faces, not {}x{}", desc.debugName,
                                desc.width, desc.height));
    if (desc.width > caps.maxCubeSize)
        throw Error(fmt::format("texture '{}': cube faces of {}x{} exceed the limit of {}", desc.debugName, desc.width,
                                desc.height, caps.maxCubeSize));
}

void checkSamplerDesc(const Capabilities& caps, const SamplerDesc& desc)
{
    // Written as negations so that NaN fails too.
    if (!(desc.minLod >= 0.0f && desc.maxLod >= desc.minLod))
        throw Error(fmt::format("sampler '{}': minLod {} and maxLod {} must satisfy 0 <= minLod <= maxLod",
                                desc.debugName, desc.minLod, desc.maxLod));
    if (!(desc.maxAnisotropy >= 1.0f && desc.maxAnisotropy <= caps.maxSamplerAnisotropy))
        throw Error(fmt::format("sampler '{}': maxAnisotropy {} is outside [1, {}], the limit of {}", desc.debugName,
                                desc.maxAnisotropy, caps.maxSamplerAnisotropy, caps.device));
}

void checkSubresource(std::string_view what, const TextureDesc& desc, std::uint32_t layer, std::uint32_t level)
{
    if (layer >= desc.layers)
        throw Error(fmt::format("{}: layer {} of texture '{}' is out of range [0, {}]", what, layer, desc.debugName,
                                desc.layers - 1));
    if (level >= desc.mipLevels)
        throw Error(fmt::format("{}: mip level {} of texture '{}' is out of range [0, {}]", what, level, desc.debugName,
                                desc.mipLevels - 1));
}

void checkTextureUpload(const TextureDesc& desc, std::uint32_t layer, std::uint32_t level, std::uint64_t size)
{
    refuseMultisampled("writeTexture", desc);
    checkSubresource("writeTexture", desc, layer, level);
    if (size != levelSize(desc, level))
        throw Error(fmt::format("writeTexture: level {} of '{}' ({}x{} {}) takes {} bytes, got {}", level,
                                desc.debugName, mipExtent(desc.width, level), mipExtent(desc.height, level),
                                formatName(desc.format), levelSize(desc, level), size));
}

void checkTextureReadback(const TextureDesc& desc, std::uint32_t layer, std::uint32_t level, const BufferDesc& buffer,
                          std::uint64_t offset)
{
    refuseMultisampled("copyTextureToBuffer", desc);
    checkSubresource("copyTextureToBuffer", desc, layer, level);
    checkBufferRange("copyTextureToBuffer", buffer, offset, levelSize(desc, level));
    const std::uint32_t alignment = isDepthFormat(desc.format) ? 4 : texelSize(desc.format);
    if (offset % alignment)
        throw Error(fmt::format("copyTextureToBuffer: offset {} is not a multiple of {} for {}", offset, alignment,
                                formatName(desc.format)));
}

void checkTextureCopy(const Texture& src, std::uint32_t srcLayer, const Texture& dst, std::uint32_t dstLayer)
{
    const TextureDesc& a = src.desc();
    const TextureDesc& b = dst.desc();
    refuseMultisampled("copyTexture source", a);
    refuseMultisampled("copyTexture destination", b);
    checkSubresource("copyTexture source", a, srcLayer, 0);
    checkSubresource("copyTexture destination", b, dstLayer, 0);
    if (a.width != b.width || a.height != b.height || a.format != b.format || a.mipLevels != b.mipLevels)
        throw Error(fmt::format("copyTexture: '{}' is {}x{} {} with {} levels but '{}' is {}x{} {} with {} levels",
                                a.debugName, a.width, a.height, formatName(a.format), a.mipLevels, b.debugName, b.width,
                                b.height, formatName(b.format), b.mipLevels));
    if (&src == &dst && srcLayer == dstLayer)
        throw Error(fmt::format("copyTexture: layer {} of '{}' onto itself", srcLayer, a.debugName));
}

void checkFramebuffer(const FramebufferDesc& desc)
{
    const Texture* first = nullptr;
    auto check = [&](const Attachment& a, bool depth) {
        const TextureDesc& t = a.texture->desc();
        if (isDepthFormat(t.format) != depth)
            throw Error(fmt::format("framebuffer '{}': texture '{}' ({}) cannot be a {} attachment", desc.debugName,
                                    t.debugName, formatName(t.format), depth ? "depth" : "colour"));
        if (!hasFlag(t.usage, TextureUsage::RenderTarget))
            throw Error(fmt::format("framebuffer '{}': texture '{}' lacks TextureUsage::RenderTarget", desc.debugName,
                                    t.debugName));
        if (a.layer >= t.layers)
            throw Error(fmt::format("framebuffer '{}': layer {} of texture '{}' is out of range [0, {}]",
                                    desc.debugName, a.layer, t.debugName, t.layers - 1));
        if (first && (first->desc().width != t.width || first->desc().height != t.height))
            throw Error(fmt::format("framebuffer '{}': texture '{}' is {}x{} but '{}' is {}x{}", desc.debugName,
                                    t.debugName, t.width, t.height, first->desc().debugName, first->desc().width,
                                    first->desc().height));
        if (first && first->desc().samples != t.samples)
            throw Error(fmt::format("framebuffer '{}': texture '{}' has {} sample(s) but '{}' has {}", desc.debugName,
                                    t.debugName, t.samples, first->desc().debugName, first->desc().samples));
        first = first ? first : a.texture;
    };
    for (const Attachment& c : desc.colors) {
        if (!c.texture)
            throw Error(fmt::format("framebuffer '{}': a colour attachment has no texture", desc.debugName));
        check(c, false);
    }
    if (desc.depth.texture)
        check(desc.depth, true);
    if (!first)
        throw Error(fmt::format("framebuffer '{}' has no attachments", desc.debugName));
}

void checkTextureResolve(const Texture& src, const Texture& dst)
{
    const TextureDesc& a = src.desc();
    const TextureDesc& b = dst.desc();
    if (a.samples == 1)
        throw Error(fmt::format("resolveTexture: source '{}' is not multisampled", a.debugName));
    if (isDepthFormat(a.format))
        throw Error(fmt::format("resolveTexture: source '{}' is {}; only colour textures are resolved", a.debugName,
                                formatName(a.format)));
    if (b.samples != 1)
        throw Error(
            fmt::format("resolveTexture: destination '{}' is multisampled ({} samples)", b.debugName, b.samples));
    if (!hasFlag(b.usage, TextureUsage::RenderTarget) || b.layers != 1)
        throw Error(
            fmt::format("resolveTexture: destination '{}' must be a RenderTarget texture of one layer", b.debugName));
    if (a.width != b.width || a.height != b.height || a.format != b.format)
        throw Error(fmt::format("resolveTexture: '{}' is {}x{} {} but '{}' is {}x{} {}", a.debugName, a.width, a.height,
                                formatName(a.format), b.debugName, b.width, b.height, formatName(b.format)));
}

void checkBufferRange(std::string_view what, const BufferDesc& buffer, std::uint64_t offset, std::uint64_t size)
{
    if (offset > buffer.size || size > buffer.size - offset)
        throw Error(fmt::format("{}: {} bytes at offset {} exceed buffer '{}' ({} bytes)", what, size, offset,
                                buffer.debugName, buffer.size));
}

void writeMappedBuffer(const BufferDesc& buffer, std::byte* mapped, std::uint64_t offset,
                       std::span<const std::byte> data)
{
    checkBufferRange("Buffer::write", buffer, offset, data.size());
    if (!data.empty())
        std::memcpy(mapped + offset, data.data(), data.size());
}

void readMappedBuffer(const BufferDesc& buffer, const std::byte* mapped, std::uint64_t offset,
                      std::span<std::byte> data)
{
    checkBufferRange("Buffer::read", buffer, offset, data.size());
    if (!data.empty())
        std::memcpy(data.data(), mapped + offset, data.size());
}

void checkBufferUsage(std::string_view what, const BufferDesc& buffer, BufferUsage usage, std::string_view usageName)
{
    if (!hasFlag(buffer.usage, usage))
        throw Error(fmt::format("{}: buffer '{}' lacks BufferUsage::{}", what, buffer.debugName, usageName));
}

void checkTimestampQueries(const Capabilities& caps, std::uint32_t count)
{
    if (!caps.timestamps)
        throw UnsupportedError(fmt::format("createTimestampQueries: {} has no timestamp queries", caps.device));
    if (count == 0)
        throw Error("createTimestampQueries: count must be at least 1");
}

} // namespace penumbra::rhi
