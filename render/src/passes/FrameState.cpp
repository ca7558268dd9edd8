#include "FrameState.hpp"

#include "../static/StaticShadowCache.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/LocalShadowPass.hpp"

#include <algorithm>

namespace penumbra::render {
namespace {

bool isStaticCaster(const std::vector<std::uint32_t>& staticCasters, std::uint32_t caster)
{
    return std::binary_search(staticCasters.begin(), staticCasters.end(), caster);
}

void readCulled(FramePassBuilder& builder, const CulledBuffers& buffers)
{
    builder.read(buffers.instances, ResourceUse::VertexRead);
    builder.read(buffers.draws, ResourceUse::IndirectRead);
}

} // namespace

SplitTiles splitStaticCasters(ShadowPlans& plans, const std::vector<std::uint32_t>& staticCasters)
{
    SplitTiles split{shadows::DirectionalShadowPass::tileDraws(plans.directional),
                     shadows::LocalShadowPass::tileDraws(plans.local)};
    for (std::vector<shadows::ShadowTileDraw>* tiles : {&split.directional, &split.local})
        for (shadows::ShadowTileDraw& tile : *tiles)
            std::erase_if(tile.casters, [&](std::uint32_t i) { return !isStaticCaster(staticCasters, i); });
    const auto drop = [&](std::vector<std::uint32_t>& casters) {
        std::erase_if(casters, [&](std::uint32_t i) { return isStaticCaster(staticCasters, i); });
    };
    for (shadows::ShadowedDirectionalLight& light : plans.directional.lights)
        for (shadows::DirectionalCascadePlan& cascade : light.cascades)
            drop(cascade.casters.casters);
    for (shadows::LocalAtlasTile& tile : plans.local.tiles)
        drop(tile.view.casters);
    return split;
}

rhi::BindingSetLayoutDesc ShadowMapBindings::layoutDesc()
{
    using K = rhi::BindingKind;
    return {.items = {{kLitShadowBinding, K::UniformBuffer},
                      {kLitAtlasBinding, K::SampledTexture},
                      {kLitLocalShadowBinding, K::UniformBuffer},
                      {kLitLocalShadowTilesBinding, K::StorageBuffer},
                      {kLitLocalAtlasBinding, K::SampledTexture},
                      {kLitShadowCubesBinding, K::SampledTexture},
                      {kLitShadowCubeDepthsBinding, K::SampledTexture},
                      {kLitStaticShadowBinding, K::UniformBuffer},
                      {kLitStaticDirectionalAtlasBinding, K::SampledTexture},
                      {kLitStaticLocalAtlasBinding, K::SampledTexture}},
            .debugName = "shadow maps"};
}

std::unique_ptr<rhi::BindingSet> ShadowMapBindings::createSet(rhi::Device& device,
                                                              const rhi::BindingSetLayout& layout) const
{
    using Item = rhi::BindingSetItem;
    const auto uniform = [](std::uint32_t binding, const rhi::UniformSlice& slice) {
        return Item::uniformBuffer(binding, *slice.buffer, slice.offset, slice.size);
    };
    const shadows::ShadowAtlas& staticDirectional = staticMaps->directionalAtlas();
    const shadows::ShadowAtlas& staticLocal = staticMaps->localAtlas();
    return device.createBindingSet(
        {.layout = &layout,
         .items = {uniform(kLitShadowBinding, directionalUniforms),
                   Item::sampledTexture(kLitAtlasBinding, directional->texture(), directional->sampler()),
                   uniform(kLitLocalShadowBinding, localUniforms),
                   Item::storageBuffer(kLitLocalShadowTilesBinding, *localTiles.buffer, localTiles.offset,
                                       localTiles.size),
                   Item::sampledTexture(kLitLocalAtlasBinding, local->texture(), local->sampler()),
                   Item::sampledTexture(kLitShadowCubesBinding, cubes->texture(), cubes->sampler()),
                   Item::sampledTexture(kLitShadowCubeDepthsBinding, cubes->texture(), cubes->depthSampler()),
                   uniform(kLitStaticShadowBinding, staticUniforms),
                   Item::sampledTexture(kLitStaticDirectionalAtlasBinding, staticDirectional.texture(),
                                        staticDirectional.sampler()),
                   Item::sampledTexture(kLitStaticLocalAtlasBinding, staticLocal.texture(), staticLocal.sampler())},
         .debugName = "shadow maps"});
}

void readShadowMaps(FramePassBuilder& builder)
{
    for (std::string_view map : {frame::kDirectionalAtlas, frame::kLocalAtlas, frame::kShadowCubes,
                                 frame::kStaticDirectionalAtlas, frame::kStaticLocalAtlas})
        builder.read(map);
}

void readLocalLights(FramePassBuilder& builder)
{
    for (std::string_view texture : {frame::kLocalLights, frame::kLightClusters, frame::kLightIndices})
        builder.read(texture);
}

void readPosedVertices(FramePassBuilder& builder, const FrameState& state)
{
    if (state.posedVertices)
        builder.read(frame::kPosedVertices, ResourceUse::VertexRead);
}

void readCulledCasters(FramePassBuilder& builder, const FrameState& state)
{
    if (state.culling)
        readCulled(builder, kCulledCasters);
}

void readLitDraws(FramePassBuilder& builder, const FrameState& state)
{
    readPosedVertices(builder, state);
    if (state.viewCulling)
        readCulled(builder, kViewCulled);
}

} // namespace penumbra::render
