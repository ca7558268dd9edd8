#include "penumbra/shadows/ShadowCasterDraws.hpp"

#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"
#include "penumbra/shadows/ShaderInterface.hpp"

#include <fmt/format.h>
#include <glm/gtc/matrix_access.hpp>
#include <glm/matrix.hpp>

namespace penumbra::shadows {
namespace {

rhi::ShaderSource casterShader(std::string_view fileName)
{
    rhi::ShaderSource source = shaders::load(fileName);
    source.includes.push_back({"caster_constants.glsl", casterConstantsGlsl()});
    return source;
}

ShadowCasterUniforms casterUniforms(const ShadowViewDraw& view, const ShadowCaster& caster, float pancakeInShader)
{
    ShadowCasterUniforms u{view.viewProjection * caster.model,
                           {caster.alpha, caster.alphaCutoff, static_cast<float>(caster.mode), pancakeInShader},
                           {view.ditherOrigin, caster.textured ? 1.0f : 0.0f, 0.0f},
                           caster.baseColorUv};
    if (view.normalOffset.reach > 0.0f) {
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(caster.model)));
        u.model = caster.model;
        for (int row = 0; row < 3; ++row)
            u.normalRows[std::size_t(row)] = glm::vec4(glm::row(normalMatrix, row), 0.0f);
        u.viewProjection = view.viewProjection;
        u.light = view.normalOffset.light;
        u.reach = {view.normalOffset.reach, 0.0f, 0.0f, 0.0f};
    }
    return u;
}

} // namespace

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
      uniforms_(device, "shadow caster draws")
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
    desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer, .clamp = clamp};
    desc.depthFormat = depthFormat;
    desc.uniformLayouts = {shadowCasterLayout()};
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

std::uint32_t ShadowCasterDraws::draw(rhi::CommandList& commands, rhi::Format depthFormat, const ShadowViewDraw& view,
                                      std::span<const std::uint32_t> indices, std::span<const ShadowCaster> casters)
{
    const bool depthClamp = view.pancake && device_.capabilities().depthClamp;
    const float pancakeInShader = view.pancake && !depthClamp ? 1.0f : 0.0f;
    const Pipelines& pipelines = this->pipelines(depthFormat, depthClamp, view.mirrored);
    const rhi::DepthBias bias{0.0f, view.slopeScaleBias, 0.0f};
    const rhi::Pipeline* bound = nullptr;
    for (const std::uint32_t index : indices) {
        if (index >= casters.size())
            throw rhi::Error(
                fmt::format("shadow plan names caster {}, but {} casters were given", index, casters.size()));
        const ShadowCaster& caster = casters[index];
        const auto& variants = caster.mode == ShadowCasterMode::Opaque ? pipelines.opaque : pipelines.alphaTested;
        const rhi::Pipeline* pipeline = variants[caster.doubleSided].get();
        if (pipeline != bound) {
            commands.bindPipeline(*pipeline);
            commands.setDepthBias(bias);
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
        commands.drawIndexed(caster.indexCount);
    }
    return static_cast<std::uint32_t>(indices.size());
}

} // namespace penumbra::shadows
