#include "LitDraws.hpp"

#include "GpuViewCulling.hpp"

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/shadows/InstanceBatches.hpp"
#include "penumbra/shadows/InstanceTransform.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

namespace penumbra::render {
namespace {

// The lit shaders compare the material's caster mode against the caster pass's PENUMBRA_CASTER_* (material.glsl).
static_assert(static_cast<int>(scene::CasterMode::Clip) == static_cast<int>(shadows::ShadowCasterMode::Clip) &&
              static_cast<int>(scene::CasterMode::Dither) == static_cast<int>(shadows::ShadowCasterMode::Dither));

constexpr std::uint32_t kNoObject = 0xffffffffu;

} // namespace

LitRole litRole(const scene::Scene& scene, const scene::Object& object)
{
    if (object.castShadows == scene::ShadowCasting::ShadowsOnly)
        return LitRole::None;
    return scene.materialOf(object).blend ? LitRole::Blended : LitRole::Opaque;
}

LitObjectUniforms litObjectUniforms(const scene::Scene& scene, const scene::Object& object)
{
    const scene::Material& material = scene.materialOf(object);
    LitObjectUniforms u{
        .baseColor = material.baseColor,
        .metallic = material.metallic,
        .roughness = material.roughness,
        .alphaCutoff = material.alphaCutoff,
        .casterMode = static_cast<std::int32_t>(material.caster),
        .receivesShadows = scene.receivesShadows(object) ? 1 : 0,
        .materialMaps = static_cast<int>(litMaterialMaps(material)),
        .unlit = material.unlit ? 1 : 0,
        .blended = material.blend ? 1 : 0,
        .emissive = material.emissive,
        .occlusionStrength = material.occlusionStrength,
        .normalScale = material.normalScale,
    };
    for (std::uint32_t slot = 0; slot < scene::kTextureSlots; ++slot) {
        const shadows::UvTransformRows rows = GpuScene::uvTransform(material.textures[slot]);
        u.uvTransforms[2 * slot] = rows[0];
        u.uvTransforms[2 * slot + 1] = rows[1];
    }
    return u;
}

std::vector<LitDraw> litDraws(const GpuScene& gpuScene, const glm::vec3& camera, const scene::ViewFrustum& frustum,
                              bool instanced, rhi::UniformArena& uniforms, rhi::VertexArena& instances,
                              const GpuViewCulling* culled)
{
    const scene::Scene& scene = gpuScene.scene();
    const auto group = [&](std::uint32_t object) {
        return instanced ? gpuScene.litDrawGroup(object) : shadows::kNoDrawGroup;
    };
    std::vector<std::uint32_t> opaque, blended;
    // Per lit draw group, its first opaque object in the scene: the groups' order.
    std::vector<std::uint32_t> firstOfGroup;
    std::vector<LitDraw> draws;
    if (culled) {
        culled->appendDraws(gpuScene, uniforms, draws);
        for (const std::uint32_t i : culled->blended())
            if (frustum.mayShow(scene.objects[i].worldBounds))
                blended.push_back(i);
    } else {
        for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
            const scene::Object& object = scene.objects[i];
            const LitRole role = litRole(scene, object);
            if (role == LitRole::None)
                continue;
            if (role == LitRole::Opaque && group(i) != shadows::kNoDrawGroup) {
                firstOfGroup.resize(std::max<std::size_t>(firstOfGroup.size(), group(i) + 1), kNoObject);
                firstOfGroup[group(i)] = std::min(firstOfGroup[group(i)], i);
            }
            if (frustum.mayShow(object.worldBounds))
                (role == LitRole::Blended ? blended : opaque).push_back(i);
        }
    }
    const auto distance2 = [&](std::uint32_t i) {
        const glm::vec3 d = scene.objects[i].worldBounds.center() - camera;
        return glm::dot(d, d);
    };
    std::stable_sort(blended.begin(), blended.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return distance2(a) > distance2(b); });
    std::vector<shadows::InstanceTransform> transforms;
    for (const bool blending : {false, true}) {
        shadows::InstanceBatches batches =
            blending ? shadows::batchRuns(std::span(blended), group) : shadows::batchByGroup(std::span(opaque), group);
        if (!blending)
            std::stable_sort(batches.batches.begin(), batches.batches.end(), [&](const auto& a, const auto& b) {
                const auto rank = [&](std::uint32_t object) {
                    return group(object) == shadows::kNoDrawGroup ? object : firstOfGroup[group(object)];
                };
                return rank(batches.items[a.first]) < rank(batches.items[b.first]);
            });
        for (const shadows::InstanceBatches::Batch& batch : batches.batches) {
            transforms.clear();
            for (std::uint32_t i = batch.first; i < batch.first + batch.count; ++i)
                transforms.push_back(shadows::instanceTransform(scene.objects[batches.items[i]].transform));
            const std::uint32_t object = batches.items[batch.first];
            draws.push_back({object, batch.count, uniforms.push(litObjectUniforms(scene, scene.objects[object])),
                             instances.push(std::as_bytes(std::span(transforms)))});
        }
    }
    return draws;
}

void recordLitDraw(rhi::CommandList& commands, const GpuScene& gpuScene, const LitDraw& draw)
{
    const scene::Object& object = gpuScene.scene().objects[draw.object];
    if (!draw.culling) {
        gpuScene.drawWithMaps(commands, object, kLitMaterialMapBinding, kLitCoverageMapBinding, draw.instances,
                              draw.instanceCount);
        return;
    }
    // The draw's firstInstance places its instances in the view's range; a group without any in view draws none. In
    // the counted form, as the atlas passes draw: on Mesa 22.3 (llvmpipe and lavapipe) the uncounted form of the same
    // arguments drew nothing in some views, while the RHI's tests of it pass; the cause is not traced
    // (cli.render-gltf-materials-gpu-culling; docs/notes/2026-12-07-view-culling.md).
    gpuScene.bindWithMaps(commands, object, kLitMaterialMapBinding, kLitCoverageMapBinding, draw.instances);
    commands.drawIndexedIndirectCount(draw.culling->draws(), draw.culling->drawOffset(0, draw.batch),
                                      draw.culling->drawCounts(), draw.culling->countOffset(0, draw.batch), 1);
}

} // namespace penumbra::render
