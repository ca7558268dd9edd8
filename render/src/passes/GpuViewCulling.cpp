#include "GpuViewCulling.hpp"

#include "penumbra/shadows/CasterVolume.hpp"

namespace penumbra::render {

void GpuViewCulling::rebuild(const GpuScene& gpuScene)
{
    const scene::Scene& scene = gpuScene.scene();
    objects_.clear();
    instances_.clear();
    bounds_.clear();
    blended_.clear();
    listedAs_.assign(scene.objects.size(), kNotListed);
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const scene::Object& object = scene.objects[i];
        const LitRole role = litRole(scene, object);
        if (role == LitRole::Blended)
            blended_.push_back(i);
        if (role != LitRole::Opaque)
            continue;
        listedAs_[i] = static_cast<std::uint32_t>(objects_.size());
        objects_.push_back(i);
        instances_.push_back({.vertices = &gpuScene.vertices(object.mesh),
                              .indices = &gpuScene.indices(object.mesh),
                              .indexCount = static_cast<std::uint32_t>(scene.meshOf(object).indices.size()),
                              .model = object.transform,
                              .drawGroup = gpuScene.litDrawGroup(i)});
        bounds_.push_back({object.worldBounds.min, object.worldBounds.max});
    }
    changes_.changedAll();
}

void GpuViewCulling::prepare(const GpuScene& gpuScene, const scene::Camera& camera, float aspect)
{
    const shadows::CasterChanges& objectChanges = gpuScene.objectChanges();
    const std::optional<std::vector<shadows::CasterRange>> changed = objectChanges.since(generation_);
    generation_ = objectChanges.generation();
    if (!changed) {
        rebuild(gpuScene);
    } else {
        const scene::Scene& scene = gpuScene.scene();
        for (const shadows::CasterRange& range : *changed)
            for (std::uint32_t object = range.first; object < range.first + range.count; ++object)
                if (const std::uint32_t listed = listedAs_[object]; listed != kNotListed) {
                    instances_[listed].model = scene.objects[object].transform;
                    bounds_[listed] = {scene.objects[object].worldBounds.min, scene.objects[object].worldBounds.max};
                    changes_.changed(listed);
                }
    }
    changes_.advance();
    const shadows::CasterVolume view =
        shadows::frustumVolume(camera.view(), camera.fovY, aspect, camera.nearPlane, camera.farPlane);
    culling_.prepare(instances_, bounds_, {&view, 1}, &changes_);
}

void GpuViewCulling::appendDraws(const GpuScene& gpuScene, rhi::UniformArena& uniforms,
                                 std::vector<LitDraw>& draws) const
{
    const scene::Scene& scene = gpuScene.scene();
    const shadows::InstanceBatches& batches = culling_.batches();
    for (std::uint32_t b = 0; b < batches.batches.size(); ++b) {
        const std::uint32_t object = objects_[batches.items[batches.batches[b].first]];
        draws.push_back({.object = object,
                         .uniforms = uniforms.push(litObjectUniforms(scene, scene.objects[object])),
                         .instances = {&culling_.instances(), 0, culling_.instances().desc().size},
                         .culling = &culling_,
                         .batch = b});
    }
}

} // namespace penumbra::render
