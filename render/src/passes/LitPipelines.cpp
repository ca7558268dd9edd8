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
    : device_(device), vertex_(vertex), fragment_(fragment), prepassedFragment_(prepassedFragment), samples_(samples)
{
}

std::unique_ptr<rhi::Pipeline> LitPipelines::create(bool doubleSided, bool blend, bool prepassed) const
{
    rhi::PipelineDesc desc;
    desc.vertex = &vertex_;
    desc.fragment = prepassed ? &prepassedFragment_ : &fragment_;
    desc.vertexLayout = GpuScene::vertexLayout();
    desc.depthFormat = kLitDepthFormat;
    desc.samples = samples_;
    desc.uniformLayouts = {litFrameLayout(), litObjectLayout(), shadows::directionalShadowLayout(),
                           shadows::otherShadowLayout(), shadows::staticShadowLayout()};
    desc.cull = doubleSided ? rhi::CullMode::None : rhi::CullMode::Back;
    rhi::ColorTarget target{kLitColorFormat};
    if (prepassed) {
        desc.depth = {.test = true, .write = false, .compare = rhi::DepthTest::Equal};
        desc.debugName = fmt::format("lit (after the depth prepass, {}{})", doubleSided ? "double-sided" : "culled",
                                     samplesSuffix(samples_));
    } else {
        desc.depth = {.test = true, .write = !blend, .compare = rhi::DepthTest::Nearer};
        if (blend)
            target.blend = {true, rhi::BlendFactor::SrcAlpha, rhi::BlendFactor::OneMinusSrcAlpha, rhi::BlendOp::Add,
                            rhi::BlendFactor::One, rhi::BlendFactor::OneMinusSrcAlpha, rhi::BlendOp::Add};
        desc.debugName = fmt::format("lit ({}, {}{})", blend ? "blended" : "opaque",
                                     doubleSided ? "double-sided" : "culled", samplesSuffix(samples_));
    }
    desc.colorTargets = {target};
    return device_.createPipeline(desc);
}

const rhi::Pipeline& LitPipelines::choose(bool doubleSided, bool blend, bool prepassed)
{
    const bool afterPrepass = prepassed && !blend;
    std::unique_ptr<rhi::Pipeline>& pipeline =
        afterPrepass ? prepassed_[doubleSided ? 1 : 0] : forward_[pipelineIndex(doubleSided, blend)];
    if (!pipeline)
        pipeline = create(doubleSided, blend, afterPrepass);
    return *pipeline;
}

} // namespace penumbra::render
