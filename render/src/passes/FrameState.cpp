#include "FrameState.hpp"

#include "../static/StaticShadowCache.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {

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

} // namespace penumbra::render
