#include "penumbra/shadows/ShadowCasterDraws.hpp"

#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"
#include "penumbra/shadows/InstanceTransform.hpp"
#include "penumbra/shadows/ShaderInterface.hpp"

#include <fmt/format.h>
#include <vector>

namespace penumbra::shadows {
namespace {

rhi::ShaderSource casterShader(std::string_view fileName)
{
    rhi::ShaderSource source = shaders::load(fileName);
    source.includes.push_back({"caster_constants.glsl", casterConstantsGlsl()});
    source.includes.push_back({"instance_constants.glsl", instanceConstantsGlsl()});
    source.includes.push_back(
        {"caster_block.glsl", shaders::uniformBlockGlsl(kShadowCasterBlock, kCasterDrawBinding, "draw")});
    return source;
}

ShadowCasterUniforms casterUniforms(const ShadowViewDraw& view, const ShadowCaster& caster, bool pancakeInShader)
{
    ShadowCasterUniforms u{.viewProjection = view.viewProjection,
                           .alpha = caster.alpha,
                           .alphaCutoff = caster.alphaCutoff,
                           .casterMode = static_cast<std::int32_t>(caster.mode),
                           .pancake = pancakeInShader ? 1 : 0,
                           .ditherOrigin = view.ditherOrigin,
                           .textured = caster.textured ? 1 : 0,
                           .baseColorUv = caster.baseColorUv};
    if (view.normalOffset.reach > 0.0f) {
        u.light = view.normalOffset.light;
        u.reach = view.normalOffset.reach;
    }
    return u;
}

// The instances of one batch.
std::vector<InstanceTransform> batchInstances(std::span<const std::uint32_t> batch,
                                              std::span<const ShadowCaster> casters)
{
    std::vector<InstanceTransform> instances;
    instances.reserve(batch.size());
    for (const std::uint32_t index : batch)
        instances.push_back(instanceTransform(casters[index].model));
    return instances;
}

} // namespace

bool drawAlike(const ShadowCaster& a, const ShadowCaster& b)
{
    return a.vertices == b.vertices && a.indices == b.indices && a.indexCount == b.indexCount && a.mode == b.mode &&
           a.alpha == b.alpha && a.alphaCutoff == b.alphaCutoff && a.baseColorMap == b.baseColorMap &&
           a.baseColorSampler == b.baseColorSampler && a.textured == b.textured && a.baseColorUv == b.baseColorUv &&
           a.doubleSided == b.doubleSided;
}

UvTransformRows uvTransformRows(const glm::mat3& m, std::uint32_t uvSet)
{
    return {glm::vec4(m[0][0], m[1][0], m[2][0], static_cast<float>(uvSet)),
            glm::vec4(m[0][1], m[1][1], m[2][1], 0.0f)};
}

rhi::Rect scissorOf(const rhi::Viewport& v)
{
    return {static_cast<std::int32_t>(v.x), static_cast<std::int32_t>(v.y), static_cast<std::uint32_t>(v.width),
            static_cast<std::uint32_t>(v.height)};
}

ShadowCasterDraws::ShadowCasterDraws(rhi::Device& device, const CasterVertexFormat& vertexFormat)
    : device_(device), vertexFormat_(vertexFormat), vertex_(device.createShader(casterShader("shadow_caster.vert"))),
      opaqueFragment_(device.createShader(casterShader("shadow_caster_opaque.frag"))),
      alphaFragment_(device.createShader(casterShader("shadow_caster_alpha.frag"))),
      uniforms_(device, "shadow caster draws"), instances_(device, "shadow caster instances")
{
}

const ShadowCasterDraws::Pipelines& ShadowCasterDraws::pipelines(rhi::Format depthFormat, bool clamp, bool mirrored)
{
    const auto key = std::make_tuple(depthFormat, clamp, mirrored);
    auto found = pipelines_.find(key);
    if (found != pipelines_.end())
        return found->second;
    rhi::PipelineDesc desc;
    desc.vertex = vertex_.get();
    desc.vertexLayout = {{{vertexFormat_.stride, false}},
                         {{0, rhi::VertexFormat::Float3, vertexFormat_.positionOffset, 0},
                          {1, rhi::VertexFormat::Float3, vertexFormat_.normalOffset, 0},
                          {2, rhi::VertexFormat::Float2, vertexFormat_.uvOffset, 0},
                          {3, rhi::VertexFormat::Float2, vertexFormat_.uv1Offset, 0}}};
    addInstanceAttributes(desc.vertexLayout, kInstanceSlot);
    desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer, .clamp = clamp};
    desc.depthFormat = depthFormat;
    desc.uniformLayouts = {shaders::uniformLayout(kShadowCasterBlock)};
    Pipelines created;
    for (const bool doubleSided : {false, true}) {
        // Casters render their light-facing side, also through the mirrored cube face views; double-sided
        // ones both sides.
        desc.cull = doubleSided ? rhi::CullMode::None
                                : (mirrored ? rhi::cubeFaceCullMode(rhi::CullMode::Back) : rhi::CullMode::Back);
        desc.fragment = opaqueFragment_.get();
        desc.debugName = doubleSided ? "shadow casters (opaque, double-sided)" : "shadow casters (opaque)";
        created.opaque[doubleSided] = device_.createPipeline(desc);
        desc.fragment = alphaFragment_.get();
        desc.debugName = doubleSided ? "shadow casters (clip, dither, double-sided)" : "shadow casters (clip, dither)";
        created.alphaTested[doubleSided] = device_.createPipeline(desc);
    }
    return pipelines_.emplace(key, std::move(created)).first->second;
}

void ShadowCasterDraws::bindBatch(rhi::CommandList& commands, const Pipelines& pipelines, const ShadowViewDraw& view,
                                  const ShadowCaster& caster, std::uint32_t index, const rhi::Pipeline*& bound)
{
    const bool pancakeInShader = view.pancake && !device_.capabilities().depthClamp;
    const auto& variants = caster.mode == ShadowCasterMode::Opaque ? pipelines.opaque : pipelines.alphaTested;
    const rhi::Pipeline* pipeline = variants[caster.doubleSided].get();
    if (pipeline != bound) {
        commands.bindPipeline(*pipeline);
        commands.setDepthBias({view.depthBias, view.slopeScaleBias, 0.0f});
        bound = pipeline;
    }
    rhi::bindUniform(commands, kCasterDrawBinding, uniforms_.push(casterUniforms(view, caster, pancakeInShader)));
    if (caster.mode != ShadowCasterMode::Opaque) {
        if (!caster.baseColorMap || !caster.baseColorSampler)
            throw rhi::Error(fmt::format("shadow caster {}: clip and dither casters need a base colour texture "
                                         "and sampler",
                                         index));
        commands.bindTexture(kCasterBaseColorBinding, *caster.baseColorMap, *caster.baseColorSampler);
    }
    commands.bindVertexBuffer(0, *caster.vertices);
    commands.bindIndexBuffer(*caster.indices, rhi::IndexType::UInt32);
}

std::uint32_t ShadowCasterDraws::draw(rhi::CommandList& commands, rhi::Format depthFormat, const ShadowViewDraw& view,
                                      std::span<const std::uint32_t> indices, std::span<const ShadowCaster> casters)
{
    const Pipelines& pipelines =
        this->pipelines(depthFormat, view.pancake && device_.capabilities().depthClamp, view.mirrored);
    for (const std::uint32_t index : indices)
        if (index >= casters.size())
            throw rhi::Error(
                fmt::format("shadow plan names caster {}, but {} casters were given", index, casters.size()));
    // Depth-only draws: the nearest caster wins in any order, so every caster of a group joins one draw.
    const InstanceBatches batches =
        batchByGroup(indices, [&](std::uint32_t index) { return casters[index].drawGroup; });
    const rhi::Pipeline* bound = nullptr;
    for (const InstanceBatches::Batch& batchRange : batches.batches) {
        const auto batch = std::span(batches.items).subspan(batchRange.first, batchRange.count);
        const std::uint32_t index = batch.front();
        const ShadowCaster& caster = casters[index];
        for (const std::uint32_t other : batch.subspan(1))
            if (!drawAlike(caster, casters[other]))
                throw rhi::Error(
                    fmt::format("shadow casters {} and {} share draw group {}, but draw differently (mesh, "
                                "material or sides)",
                                index, other, caster.drawGroup));
        bindBatch(commands, pipelines, view, caster, index, bound);
        const std::vector<InstanceTransform> instances = batchInstances(batch, casters);
        const rhi::BufferSlice instanceSlice = instances_.push(std::as_bytes(std::span(instances)));
        commands.bindVertexBuffer(kInstanceSlot, *instanceSlice.buffer, instanceSlice.offset);
        commands.drawIndexed(caster.indexCount, batchRange.count);
    }
    return static_cast<std::uint32_t>(batches.batches.size());
}

std::uint32_t ShadowCasterDraws::drawCulled(rhi::CommandList& commands, rhi::Format depthFormat,
                                            const ShadowViewDraw& view, const GpuCasterCulling& culling,
                                            std::uint32_t tile, std::span<const ShadowCaster> casters)
{
    const Pipelines& pipelines =
        this->pipelines(depthFormat, view.pancake && device_.capabilities().depthClamp, view.mirrored);
    const InstanceBatches& batches = culling.batches();
    const rhi::Pipeline* bound = nullptr;
    for (std::uint32_t b = 0; b < batches.batches.size(); ++b) {
        const std::uint32_t index = batches.items[batches.batches[b].first];
        bindBatch(commands, pipelines, view, casters[index], index, bound);
        // The draw's firstInstance places its instances in the tile's range; a batch without any draws nothing.
        commands.bindVertexBuffer(kInstanceSlot, culling.instances());
        commands.drawIndexedIndirectCount(culling.draws(), culling.drawOffset(tile, b), culling.drawCounts(),
                                          culling.countOffset(tile, b), 1);
    }
    return static_cast<std::uint32_t>(batches.batches.size());
}

} // namespace penumbra::shadows
