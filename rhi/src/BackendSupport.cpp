#include "penumbra/rhi/BackendSupport.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::rhi {

LodRange samplerLodRange(const SamplerDesc& desc)
{
    if (desc.mipFilter == MipFilter::None)
        return {0.0f, 0.25f};
    return {desc.minLod, desc.maxLod};
}

ComputePipeline::ComputePipeline(const CompiledShader& shader)
    : bindings_(shader.bindings), workgroupSize_(shader.workgroupSize)
{
    std::sort(bindings_.begin(), bindings_.end(),
              [](const ShaderBinding& a, const ShaderBinding& b) { return a.binding < b.binding; });
}

std::vector<ShaderBinding> pipelineBindings(const PipelineDesc& desc)
{
    std::vector<ShaderBinding> all = desc.vertex->compiled().bindings;
    for (const ShaderBinding& b : desc.fragment->compiled().bindings) {
        auto same =
            std::find_if(all.begin(), all.end(), [&](const ShaderBinding& a) { return a.binding == b.binding; });
        if (same == all.end())
            all.push_back(b);
        else if (same->kind != b.kind)
            throw Error(fmt::format("pipeline '{}': binding {} is '{}' in {} but '{}' in {}", desc.debugName, b.binding,
                                    same->name, desc.vertex->compiled().name, b.name, desc.fragment->compiled().name));
    }
    std::sort(all.begin(), all.end(),
              [](const ShaderBinding& a, const ShaderBinding& b) { return a.binding < b.binding; });
    return all;
}

DepthBias signedDepthBias(const Conventions& conventions, const DepthBias& bias)
{
    const float sign = conventions.depthBiasSign();
    return {bias.constant * sign, bias.slope * sign, bias.clamp * sign};
}

AttachmentFormats attachmentFormats(const FramebufferDesc& desc)
{
    AttachmentFormats formats;
    for (const Attachment& c : desc.colors)
        formats.colors.push_back(c.texture->desc().format);
    if (desc.depth.texture)
        formats.depth = desc.depth.texture->desc().format;
    const Texture* any = desc.colors.empty() ? desc.depth.texture : desc.colors.front().texture;
    formats.samples = any ? any->desc().samples : 1;
    return formats;
}

std::uint64_t levelSize(const TextureDesc& desc, std::uint32_t level)
{
    return std::uint64_t(mipExtent(desc.width, level)) * mipExtent(desc.height, level) * texelSize(desc.format);
}

std::string_view formatName(Format f)
{
    switch (f) {
    case Format::RGBA8:
        return "RGBA8";
    case Format::RGBA16F:
        return "RGBA16F";
    case Format::RGBA32F:
        return "RGBA32F";
    case Format::D16:
        return "D16";
    case Format::D24S8:
        return "D24S8";
    case Format::D32F:
        return "D32F";
    case Format::RGBA8_SRGB:
        return "RGBA8_SRGB";
    case Format::R8:
        return "R8";
    case Format::RG8:
        return "RG8";
    case Format::R16F:
        return "R16F";
    case Format::RG16F:
        return "RG16F";
    case Format::R32F:
        return "R32F";
    }
    return "unknown";
}

} // namespace penumbra::rhi
