#include "penumbra/rhi/BackendSupport.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::rhi {

void checkTextureBinding(const Capabilities& caps, const Texture& texture, const Sampler& sampler)
{
    const Format format = texture.desc().format;
    if (isDepthFormat(format) && sampler.desc().filter == Filter::Linear && !caps.supportsLinearFilter(format))
        throw UnsupportedError(fmt::format(
            "texture '{}' ({}) with linear sampler '{}': this driver ({}) cannot filter {} linearly; "
            "use a nearest sampler and filter in the shader",
            texture.desc().debugName, formatName(format), sampler.desc().debugName, caps.device, formatName(format)));
}

void checkTextureDesc(const Capabilities& caps, const TextureDesc& desc)
{
    if (desc.width == 0 || desc.height == 0 || desc.layers == 0 || desc.width > caps.maxTextureSize ||
        desc.height > caps.maxTextureSize || desc.layers > caps.maxTextureLayers)
        throw Error(fmt::format("texture '{}': {}x{} with {} layers is outside 1..{} texels and 1..{} layers",
                                desc.debugName, desc.width, desc.height, desc.layers, caps.maxTextureSize,
                                caps.maxTextureLayers));
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

void checkPipeline(const PipelineDesc& desc)
{
    if (!desc.vertex || !desc.fragment)
        throw Error(fmt::format("pipeline '{}' needs a vertex and a fragment shader", desc.debugName));
    if (desc.vertex->compiled().stage != ShaderStage::Vertex || desc.fragment->compiled().stage != ShaderStage::Fragment)
        throw Error(fmt::format("pipeline '{}': shader stages are swapped", desc.debugName));
    if (desc.depthFormat && !isDepthFormat(*desc.depthFormat))
        throw Error(fmt::format("pipeline '{}': depthFormat {} is not a depth format", desc.debugName,
                                formatName(*desc.depthFormat)));
    for (const ColorTarget& c : desc.colorTargets)
        if (isDepthFormat(c.format))
            throw Error(fmt::format("pipeline '{}': colour target format {} is a depth format", desc.debugName,
                                    formatName(c.format)));
    pipelineBindings(desc);
}

std::vector<ShaderBinding> pipelineBindings(const PipelineDesc& desc)
{
    std::vector<ShaderBinding> all = desc.vertex->compiled().bindings;
    for (const ShaderBinding& b : desc.fragment->compiled().bindings) {
        auto same = std::find_if(all.begin(), all.end(), [&](const ShaderBinding& a) { return a.binding == b.binding; });
        if (same == all.end())
            all.push_back(b);
        else if (same->kind != b.kind)
            throw Error(fmt::format("pipeline '{}': binding {} is '{}' in {} but '{}' in {}", desc.debugName,
                                    b.binding, same->name, desc.vertex->compiled().name, b.name,
                                    desc.fragment->compiled().name));
    }
    std::sort(all.begin(), all.end(), [](const ShaderBinding& a, const ShaderBinding& b) { return a.binding < b.binding; });
    return all;
}

DepthBias signedDepthBias(const Conventions& conventions, const DepthBias& bias)
{
    const float sign = conventions.depthBiasSign();
    return {bias.constant * sign, bias.slope * sign, bias.clamp * sign};
}

std::uint64_t layerSize(const TextureDesc& desc)
{
    return std::uint64_t(desc.width) * desc.height * texelSize(desc.format);
}

std::string_view formatName(Format f)
{
    switch (f) {
    case Format::RGBA8: return "RGBA8";
    case Format::RGBA16F: return "RGBA16F";
    case Format::RGBA32F: return "RGBA32F";
    case Format::D16: return "D16";
    case Format::D24S8: return "D24S8";
    case Format::D32F: return "D32F";
    }
    return "unknown";
}

} // namespace penumbra::rhi
