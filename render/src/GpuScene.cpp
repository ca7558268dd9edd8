#include "penumbra/render/GpuScene.hpp"

#include <cstddef>

namespace penumbra::render {
namespace {

std::optional<shadows::ShadowCasterMode> casterMode(scene::CasterMode mode)
{
    switch (mode) {
    case scene::CasterMode::On: return shadows::ShadowCasterMode::Opaque;
    case scene::CasterMode::Clip: return shadows::ShadowCasterMode::Clip;
    case scene::CasterMode::Dither: return shadows::ShadowCasterMode::Dither;
    case scene::CasterMode::Off: break;
    }
    return std::nullopt;
}

template <typename T>
std::unique_ptr<rhi::Buffer> upload(rhi::Device& device, const std::vector<T>& data, rhi::BufferUsage usage,
                                    const std::string& name)
{
    auto buffer = device.createBuffer({.size = data.size() * sizeof(T), .usage = usage, .debugName = name});
    buffer->write(0, std::as_bytes(std::span(data)));
    return buffer;
}

} // namespace

GpuScene::GpuScene(rhi::Device& device, const scene::Scene& scene) : scene_(scene)
{
    scene.validate();
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const scene::MeshData& mesh = scene.meshes[i];
        const std::string name = "mesh " + std::to_string(i);
        meshes_.push_back({upload(device, mesh.vertices, rhi::BufferUsage::Vertex, name + " vertices"),
                           upload(device, mesh.indices, rhi::BufferUsage::Index, name + " indices")});
    }
}

std::vector<shadows::ShadowCaster> GpuScene::casters() const
{
    std::vector<shadows::ShadowCaster> casters;
    for (const scene::Object& object : scene_.objects) {
        const scene::Material& material = scene_.materialOf(object);
        if (const auto mode = casterMode(material.caster))
            casters.push_back({meshes_[object.mesh].vertices.get(), meshes_[object.mesh].indices.get(),
                               static_cast<std::uint32_t>(scene_.meshOf(object).indices.size()), object.transform,
                               *mode, material.baseColor.a, material.alphaCutoff});
    }
    return casters;
}

std::vector<shadows::Bounds> GpuScene::casterBounds() const
{
    std::vector<shadows::Bounds> bounds;
    for (const scene::Object& object : scene_.objects)
        if (casterMode(scene_.materialOf(object).caster))
            bounds.push_back({object.worldBounds.min, object.worldBounds.max});
    return bounds;
}

shadows::CasterVertexFormat GpuScene::vertexFormat()
{
    return {sizeof(scene::Vertex), offsetof(scene::Vertex, position), offsetof(scene::Vertex, uv)};
}

} // namespace penumbra::render
