#include "LitPipelines.hpp"

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/OtherShadowUniforms.hpp"
#include "penumbra/shadows/StaticShadowUniforms.hpp"

#include <fmt/format.h>

namespace penumbra::render {
namespace {

std::uint32_t pipelineIndex(bool doubleSided, bool blend) { return (doubleSided ? 1u : 0u) + (blend ? 2u : 0u); }

std::string samplesSuffix(std::uint32_t samples)
{
    return samples > 1 ? fmt::format(", {}x MSAA", samples) : std::string();
}

} // namespace

LitPipelines::LitPipelines(rhi::Device& device, const rhi::Shader& vertex, const rhi::Shader& fragment,
                           const rhi::Shader& prepassedFragment, std::uint32_t samples)
    : samples_(samples)
{
    rhi::PipelineDesc desc;
    desc.vertex = &vertex;
    desc.fragment = &fragment;
    desc.vertexLayout = GpuScene::vertexLayout();
    desc.depthFormat = kLitDepthFormat;
    desc.samples = samples;
    desc.uniformLayouts = {litFrameLayout(), litObjectLayout(), shadows::directionalShadowLayout(),
                           shadows::otherShadowLayout(), shadows::staticShadowLayout()};
    for (const bool blend : {false, true})
        for (const bool doubleSided : {false, true}) {
            desc.cull = doubleSided ? rhi::CullMode::None : rhi::CullMode::Back;
            desc.depth = {.test = true, .write = !blend, .compare = rhi::DepthTest::Nearer};
            rhi::ColorTarget target{kLitColorFormat};
            if (blend)
                target.blend = {true, rhi::BlendFactor::SrcAlpha, rhi::BlendFactor::OneMinusSrcAlpha, rhi::BlendOp::Add,
                                rhi::BlendFactor::One, rhi::BlendFactor::OneMinusSrcAlpha, rhi::BlendOp::Add};
            desc.colorTargets = {target};
            desc.debugName = fmt::format("lit ({}, {}{})", blend ? "blended" : "opaque",
                                         doubleSided ? "double-sided" : "culled", samplesSuffix(samples));
            forward_[pipelineIndex(doubleSided, blend)] = device.createPipeline(desc);
        }
    desc.fragment = &prepassedFragment;
    desc.depth = {.test = true, .write = false, .compare = rhi::DepthTest::Equal};
    desc.colorTargets = {rhi::ColorTarget{kLitColorFormat}};
    for (const bool doubleSided : {false, true}) {
        desc.cull = doubleSided ? rhi::CullMode::None : rhi::CullMode::Back;
        desc.debugName = fmt::format("lit (after the depth prepass, {}{})", doubleSided ? "double-sided" : "culled",
                                     samplesSuffix(samples));
        prepassed_[doubleSided ? 1 : 0] = device.createPipeline(desc);
    }
}

const rhi::Pipeline& LitPipelines::choose(bool doubleSided, bool blend, bool prepassed) const
{
    return prepassed && !blend ? *prepassed_[doubleSided ? 1 : 0] : *forward_[pipelineIndex(doubleSided, blend)];
}

} // namespace penumbra::render
