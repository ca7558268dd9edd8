#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"

#include <memory>
#include <vector>

namespace penumbra::render {

// A scene's meshes in GPU buffers (vertices as scene::Vertex, 32-bit indices), and its shadow
// casters in the order the shadow planner sees their bounds.
class GpuScene {
public:
    // Validates the scene (scene::SceneError names what is wrong) and uploads every mesh and texture.
    GpuScene(rhi::Device& device, const scene::Scene& scene);

    const scene::Scene& scene() const { return scene_; }
    const rhi::Buffer& vertices(std::uint32_t mesh) const { return *meshes_.at(mesh).vertices; }
    const rhi::Buffer& indices(std::uint32_t mesh) const { return *meshes_.at(mesh).indices; }
    // The material's texture in `slot`, or a white texel for a material without one.
    const rhi::Texture& map(const scene::Material& material, scene::TextureSlot slot) const;
    const rhi::Texture& baseColorMap(const scene::Material& material) const
    {
        return map(material, scene::TextureSlot::BaseColor);
    }
    // Every material texture is sampled through this one.
    const rhi::Sampler& baseColorSampler() const { return *sampler_; }

    // Objects whose material casts shadows, with their world bounds; object transforms are read
    // from the scene on every call, so moved objects (with updated worldBounds) are seen.
    std::vector<shadows::ShadowCaster> casters() const;
    std::vector<shadows::Bounds> casterBounds() const;

    static shadows::CasterVertexFormat vertexFormat();
    // The uv transform rows of a material texture (identity on TEXCOORD_0 without one).
    static shadows::UvTransformRows uvTransform(const std::optional<scene::MaterialTexture>& texture);

private:
    struct Mesh {
        std::unique_ptr<rhi::Buffer> vertices;
        std::unique_ptr<rhi::Buffer> indices;
    };
    const scene::Scene& scene_;
    std::vector<Mesh> meshes_;
    std::vector<std::unique_ptr<rhi::Texture>> textures_;
    std::unique_ptr<rhi::Texture> white_;
    std::unique_ptr<rhi::Sampler> sampler_;
};

} // namespace penumbra::render
