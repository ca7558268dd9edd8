#include "FrameState.hpp"

#include "../static/StaticShadowCache.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {

void ShadowMapBindings::bind(rhi::CommandList& commands) const
{
    rhi::bindUniform(commands, kLitShadowBinding, directionalUniforms);
    commands.bindTexture(kLitAtlasBinding, directional->texture(), directional->sampler());
    rhi::bindUniform(commands, kLitLocalShadowBinding, localUniforms);
    commands.bindStorageBuffer(kLitLocalShadowTilesBinding, *localTiles.buffer, localTiles.offset, localTiles.size);
    commands.bindTexture(kLitLocalAtlasBinding, local->texture(), local->sampler());
    commands.bindTexture(kLitShadowCubesBinding, cubes->texture(), cubes->sampler());
    commands.bindTexture(kLitShadowCubeDepthsBinding, cubes->texture(), cubes->depthSampler());
    rhi::bindUniform(commands, kLitStaticShadowBinding, staticUniforms);
    const shadows::ShadowAtlas& staticDirectional = staticMaps->directionalAtlas();
    const shadows::ShadowAtlas& staticLocal = staticMaps->localAtlas();
    commands.bindTexture(kLitStaticDirectionalAtlasBinding, staticDirectional.texture(), staticDirectional.sampler());
    commands.bindTexture(kLitStaticLocalAtlasBinding, staticLocal.texture(), staticLocal.sampler());
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
