#include "penumbra/shadows/DirectionalShadowPass.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {
namespace {

constexpr std::uint32_t kDrawBinding = 0;

rhi::Rect scissorOf(const rhi::Viewport& v)
{
    return {static_cast<std::int32_t>(v.x), static_cast<std::int32_t>(v.y), static_cast<std::uint32_t>(v.width),
            static_cast<std::uint32_t>(v.height)};
}

} // namespace

glm::vec2 ditherOrigin(const DirectionalShadowCascade& cascade, const ShadowAtlasLayout& atlas, std::uint32_t tile)
{
    const glm::vec2 centre = glm::round(cascade.snappedCentre / cascade.texelSize);
    const glm::vec2 offset = glm::vec2(atlas.tileOffset(tile)) + 0.5f * static_cast<float>(atlas.tileSize());
    return {centre.x - offset.x, -centre.y - offset.y};
}

DirectionalShadowPass::DirectionalShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat)
    : device_(device), vertexFormat_(vertexFormat),
      vertex_(device.createShader(shaders::load("shadow_caster.vert"))),
      opaqueFragment_(device.createShader(shaders::load("shadow_caster_opaque.frag"))),
      alphaFragment_(device.createShader(shaders::load("shadow_caster_alpha.frag"))),
      uniforms_(device, "shadow caster draws")
{
}

const DirectionalShadowPass::Pipelines& DirectionalShadowPass::pipelines(rhi::Format atlasFormat)
{
    auto found = pipelines_.find(atlasFormat);
    if (found != pipelines_.end())
        return found->second;
    rhi::PipelineDesc desc;
    desc.vertex = vertex_.get();
    desc.vertexLayout = {{{vertexFormat_.stride, false}},
                         {{0, rhi::VertexFormat::Float3, vertexFormat_.positionOffset, 0},
                          {2, rhi::VertexFormat::Float2, vertexFormat_.uvOffset, 0}}};
    desc.cull = rhi::CullMode::Back;
    desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer, .clamp = device_.capabilities().depthClamp};
    desc.depthFormat = atlasFormat;
    Pipelines created;
    desc.fragment = opaqueFragment_.get();
    desc.debugName = "shadow casters (opaque)";
    created.opaque = device_.createPipeline(desc);
    desc.fragment = alphaFragment_.get();
    desc.debugName = "shadow casters (clip, dither)";
    created.alphaTested = device_.createPipeline(desc);
    return pipelines_.emplace(atlasFormat, std::move(created)).first->second;
}

std::uint32_t DirectionalShadowPass::record(rhi::CommandList& commands, const ShadowAtlas& atlas,
                                            const DirectionalShadowPlan& plan, std::span<const ShadowCaster> casters)
{
    if (atlas.size() != plan.atlas.atlasSize())
        throw rhi::Error(fmt::format("shadow atlas is {} texels wide, the plan was made for {}", atlas.size(),
                                     plan.atlas.atlasSize()));
    const Pipelines& pipelines = this->pipelines(atlas.format());
    const float pancakeInShader = device_.capabilities().depthClamp ? 0.0f : 1.0f;
    uniforms_.reset();
    std::uint32_t draws = 0;
    commands.beginPass({.framebuffer = &atlas.framebuffer(), .clearColor = std::nullopt, .clearDepth = true});
    for (const ShadowedDirectionalLight& light : plan.lights) {
        const rhi::DepthBias bias{0.0f, light.slopeScaleBias, 0.0f};
        for (const DirectionalCascadePlan& cascade : light.cascades) {
            const glm::vec4 dither(ditherOrigin(cascade.fit, plan.atlas, cascade.tile), 0.0f, 0.0f);
            commands.setViewport(cascade.viewport);
            commands.setScissor(scissorOf(cascade.viewport));
            const rhi::Pipeline* bound = nullptr;
            for (const std::uint32_t index : cascade.casters.casters) {
                if (index >= casters.size())
                    throw rhi::Error(fmt::format("shadow plan names caster {}, but {} casters were given", index,
                                                 casters.size()));
                const ShadowCaster& caster = casters[index];
                const rhi::Pipeline* pipeline =
                    caster.mode == ShadowCasterMode::Opaque ? pipelines.opaque.get() : pipelines.alphaTested.get();
                if (pipeline != bound) {
                    commands.bindPipeline(*pipeline);
                    commands.setDepthBias(bias);
                    bound = pipeline;
                }
                const ShadowCasterUniforms draw{cascade.fit.viewProjection * caster.model,
                                                {caster.alpha, caster.alphaCutoff, static_cast<float>(caster.mode),
                                                 pancakeInShader},
                                                dither};
                rhi::bindUniform(commands, kDrawBinding, uniforms_.push(draw));
                commands.bindVertexBuffer(0, *caster.vertices);
                commands.bindIndexBuffer(*caster.indices, rhi::IndexType::UInt32);
                commands.drawIndexed(caster.indexCount);
                ++draws;
            }
        }
    }
    commands.endPass();
    return draws;
}

} // namespace penumbra::shadows
