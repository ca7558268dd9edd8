#include "StaticMapHashes.hpp"

#include "ContentHash.hpp"

#include <map>

namespace penumbra::render {
namespace {

std::uint64_t objectHash(const scene::Scene& scene, const scene::Object& object,
                         std::map<std::uint32_t, std::uint64_t>& meshes)
{
    auto mesh = meshes.find(object.mesh);
    if (mesh == meshes.end()) {
        const scene::MeshData& data = scene.meshOf(object);
        ContentHash h;
        for (const scene::Vertex& v : data.vertices)
            h.add(v.position).add(v.uv).add(v.uv1);
        for (const std::uint32_t i : data.indices)
            h.add(i);
        mesh = meshes.emplace(object.mesh, h.value()).first;
    }
    const scene::Material& material = scene.materialOf(object);
    ContentHash h;
    h.add(mesh->second).add(object.transform).add(object.castShadows).add(material.caster).add(material.baseColor.a);
    h.add(material.alphaCutoff).add(material.doubleSided);
    if (const std::optional<scene::MaterialTexture>& texture = material.texture(scene::TextureSlot::BaseColor)) {
        const scene::TextureImage& image = scene.textures.at(texture->image);
        h.add(texture->texCoord).add(texture->transform.offset).add(texture->transform.rotation);
        h.add(texture->transform.scale).add(image.width).add(image.height).addBytes(image.rgba);
    }
    return h.value();
}

} // namespace

std::vector<std::uint64_t> staticMapHashes(const scene::Scene& scene, const shadows::StaticShadowPlan& plan)
{
    // Caster i of the plan is the i-th object that casts shadows (GpuScene::casters).
    std::vector<std::uint32_t> casterObjects;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        if (scene.castsShadows(scene.objects[i]))
            casterObjects.push_back(i);
    std::map<std::uint32_t, std::uint64_t> meshes;
    std::map<std::uint32_t, std::uint64_t> objects;
    std::vector<std::uint64_t> hashes;
    for (const shadows::StaticShadowMap& map : plan.maps) {
        ContentHash h;
        h.add(map.kind).add(map.lightIndex);
        for (const shadows::StaticShadowTile& tile : map.tiles) {
            const shadows::ShadowFrustum& f = tile.frustum;
            h.add(tile.viewport.width).add(f.view).add(f.perspective).add(f.extent).add(f.nearPlane).add(f.farPlane);
            h.add(tile.view.slopeScaleBias).add(tile.view.depthBias).add(tile.view.normalOffset.reach);
            for (const std::uint32_t caster : tile.casters) {
                const std::uint32_t object = casterObjects.at(caster);
                auto known = objects.find(object);
                if (known == objects.end())
                    known = objects.emplace(object, objectHash(scene, scene.objects[object], meshes)).first;
                h.add(known->second);
            }
        }
        hashes.push_back(h.value());
    }
    return hashes;
}

} // namespace penumbra::render
