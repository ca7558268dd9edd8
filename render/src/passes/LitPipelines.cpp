#include "LitPipelines.hpp"

#include "penumbra/render/GpuScene.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <vector>

namespace penumbra::render {
namespace {

std::uint32_t featureKey(const LitShaderFeatures& f)
{
    return (f.depthPrepassed ? 1u : 0u) | static_cast<std::uint32_t>(f.view) << 1 | (f.localLights ? 1u << 3 : 0u) |
           (f.staticShadows ? 1u << 4 : 0u) | (f.tentFilters ? 1u << 5 : 0u) | (f.softFilters ? 1u << 6 : 0u) |
           (f.shadowCubes ? 1u << 7 : 0u) | f.materialMaps << 8 |
           static_cast<std::uint32_t>(f.directionalShadows) << (8 + scene::kTextureSlots) |
           (f.contactShadows ? 1u << (10 + scene::kTextureSlots) : 0u);
}

std::string samplesSuffix(std::uint32_t samples)
{
    return samples > 1 ? fmt::format(", {}x MSAA", samples) : std::string();
}

bool isTent(shadows::ShadowFilter filter) { return shadows::filterFamily(filter) == shadows::ShadowFilterFamily::Tent; }

bool isSoft(shadows::ShadowFilter filter) { return shadows::isSoftFilter(filter); }

} // namespace

LitPipelines::LitPipelines(rhi::Device& device, const rhi::Shader& vertex, const rhi::BindingSetLayout& shadowMaps,
                           std::uint32_t samples)
    : device_(device), vertex_(vertex), shadowMaps_(shadowMaps), samples_(samples)
{
}

const rhi::Shader& LitPipelines::fragment(const LitShaderFeatures& features)
{
    std::unique_ptr<rhi::Shader>& shader = fragments_[featureKey(features)];
    if (!shader)
        shader = device_.createShader(litShader("lit.frag", features));
    return *shader;
}

const rhi::Pipeline& LitPipelines::choose(LitShaderFeatures features, bool doubleSided, bool blend)
{
    features.samples = samples_;
    // Blended surfaces are not in the prepass's depth, so not in the screen-space or contact shadows either.
    if (blend) {
        features.depthPrepassed = false;
        features.directionalShadows = DirectionalShadowSource::Forward;
        features.contactShadows = false;
    }
    const std::uint32_t key = featureKey(features) << 2 | (doubleSided ? 1u : 0u) | (blend ? 2u : 0u);
    std::unique_ptr<rhi::Pipeline>& pipeline = pipelines_[key];
    if (pipeline)
        return *pipeline;
    rhi::PipelineDesc desc;
    desc.vertex = &vertex_;
    desc.fragment = &fragment(features);
    desc.vertexLayout = GpuScene::vertexLayout();
    desc.depthFormat = kLitDepthFormat;
    desc.samples = samples_;
    desc.uniformLayouts = {shaders::uniformLayout(kLitFrameBlock), shaders::uniformLayout(kLitObjectBlock),
                           shaders::uniformLayout(shadows::kDirectionalShadowBlock),
                           shaders::uniformLayout(shadows::kLocalShadowBlock),
                           shaders::uniformLayout(shadows::kStaticShadowBlock)};
    desc.storageLayouts = {shaders::storageLayout(shadows::kLocalShadowTilesBlock)};
    desc.bindingSetLayouts = {&shadowMaps_};
    desc.cull = doubleSided ? rhi::CullMode::None : rhi::CullMode::Back;
    rhi::ColorTarget target{kLitColorFormat};
    if (features.depthPrepassed) {
        desc.depth = {.test = true, .write = false, .compare = rhi::DepthTest::Equal};
    } else {
        desc.depth = {.test = true, .write = !blend, .compare = rhi::DepthTest::Nearer};
        if (blend)
            target.blend = {true,
                            rhi::BlendFactor::SrcAlpha,
                            rhi::BlendFactor::OneMinusSrcAlpha,
                            rhi::BlendOp::Add,
                            rhi::BlendFactor::One,
                            rhi::BlendFactor::OneMinusSrcAlpha,
                            rhi::BlendOp::Add};
    }
    desc.colorTargets = {target};
    desc.debugName =
        fmt::format("lit ({}, {}{}, features {:#x})",
                    features.depthPrepassed ? "after the depth prepass"
                    : blend                 ? "blended"
                                            : "opaque",
                    doubleSided ? "double-sided" : "culled", samplesSuffix(samples_), featureKey(features));
    pipeline = device_.createPipeline(desc);
    return *pipeline;
}

LitShaderFeatures frameShaderFeatures(const LitFrameUniforms& frame,
                                      const shadows::DirectionalShadowUniforms& directional,
                                      const shadows::LocalShadowPlan& localPlan,
                                      const shadows::StaticShadowPlan& staticPlan)
{
    const shadows::StaticShadowUniforms& staticMaps = staticPlan.uniforms;
    const shadows::LocalShadowUniforms& local = localPlan.uniforms;
    std::vector<shadows::ShadowFilter> filters{directional.defaultFilter, local.defaultFilter};
    for (const shadows::DirectionalShadowLight& light : directional.lights)
        filters.push_back(light.shadowFilter);
    for (const shadows::LocalAtlasTileData& tile : localPlan.tileData)
        filters.push_back(tile.shadowFilter);
    for (const shadows::LocalShadowCube& cube : local.cubes)
        filters.push_back(cube.shadowFilter);
    bool staticShadows = false;
    for (const shadows::StaticDirectionalLight& light : staticMaps.directionalLights) {
        staticShadows = staticShadows || light.tile >= 0;
        filters.push_back(light.shadowFilter);
    }
    for (const shadows::StaticLocalLightMap& light : staticPlan.localLightMaps)
        staticShadows = staticShadows || light.tile >= 0;
    for (const shadows::LocalShadowTile& tile : staticMaps.localTiles)
        filters.push_back(tile.shadowFilter);
    LitShaderFeatures features;
    features.localLights = frame.localLightCount > 0;
    features.staticShadows = staticShadows;
    features.tentFilters = std::any_of(filters.begin(), filters.end(), isTent);
    features.softFilters = std::any_of(filters.begin(), filters.end(), isSoft);
    features.shadowCubes = local.pointMode == shadows::PointShadowMode::CubeMap;
    return features;
}

} // namespace penumbra::render
