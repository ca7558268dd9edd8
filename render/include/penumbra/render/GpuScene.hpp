#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/CasterChanges.hpp"
#include "penumbra/shadows/InstanceTransform.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace penumbra::render {

// A scene's meshes in GPU buffers (vertices as scene::Vertex, 32-bit indices), and its shadow
// casters in the order the shadow planner sees their bounds. A deformed mesh (scene::Rig::deformers) gets a vertex
// buffer that is also a storage buffer: the renderer's GPU skinning writes its pose into it every frame.
class GpuScene {
public:
    // Validates the scene (scene::SceneError names what is wrong) and uploads every mesh and texture, each
    // texture through one helper: colour ones (base colour, emissive; scene::TextureColorSpace::Srgb) as
    // RGBA8_SRGB, data ones (metallic-roughness, normal, occlusion) as RGBA8, with mip chains made on the CPU
    // (rhi::generateMipLevels, on hardware threads while earlier textures upload) where their samplers read mip
    // levels. Samplers start without anisotropic filtering.
    GpuScene(rhi::Device& device, const scene::Scene& scene);

    // The scene this was uploaded from.
    const scene::Scene& scene() const { return scene_; }
    // The vertex buffer of a mesh (an index into Scene::meshes).
    const rhi::Buffer& vertices(std::uint32_t mesh) const { return *meshes_.at(mesh).vertices; }
    // The index buffer of a mesh (32-bit indices).
    const rhi::Buffer& indices(std::uint32_t mesh) const { return *meshes_.at(mesh).indices; }
    // Scene::textures[*index] and the sampler its file asks for; a white texel (sampled as 1 in every
    // channel) and a bilinear sampler for nullopt.
    const rhi::Texture& texture(std::optional<std::uint32_t> index) const;
    // The sampler of a scene texture, or a bilinear sampler for nullopt.
    const rhi::Sampler& sampler(std::optional<std::uint32_t> index) const;
    // The material's texture in `slot` and the sampler of its glTF texture, or the white texel and its
    // sampler for a material without one.
    const rhi::Texture& map(const scene::Material& material, scene::TextureSlot slot) const;
    // The sampler of a material's texture in `slot`, or a bilinear one where it has none.
    const rhi::Sampler& mapSampler(const scene::Material& material, scene::TextureSlot slot) const;
    // The base colour texture of a material (white without one).
    const rhi::Texture& baseColorMap(const scene::Material& material) const
    {
        return map(material, scene::TextureSlot::BaseColor);
    }
    // The sampler of a material's base colour texture.
    const rhi::Sampler& baseColorSampler(const scene::Material& material) const
    {
        return mapSampler(material, scene::TextureSlot::BaseColor);
    }
    // The base colour map's sampler without anisotropic filtering (the white texel's sampler without one): the alpha
    // that decides coverage in every pass (the depth prepass, the lit pass's cut and blend, the shadow casters), so
    // that all of them cut the same holes, and cheaply on software rasterizers, whose anisotropic filter loops
    // over the whole footprint.
    const rhi::Sampler& coverageSampler(const scene::Material& material) const;
    // Makes every texture's sampler anew with this anisotropy (within the device's limit) where it changed.
    void setMaxAnisotropy(float anisotropy);

    // What the caster list depends on besides the scene.
    struct CasterOptions {
        // False: every caster is drawn alone (ShadowCaster::drawGroup is kNoDrawGroup).
        bool instancedDraws = true;
        // Per mesh, the vertex buffer its casters draw instead of vertices(mesh); empty, or nullptr for a mesh, to
        // draw the scene's own (the negative control that leaves skinning out of the casters draws rest poses).
        std::vector<const rhi::Buffer*> vertices;
        bool operator==(const CasterOptions&) const = default;
    };
    // Reads the scene's objects again for the caster list, bounds and static casters below, which are kept from call
    // to call: a caster is rewritten only where its object moved (transform or world bounds) or its pose changed, and
    // recorded in casterChanges(); the whole list is built anew where an object's shadow casting, shadow receiving or
    // mobility, a material, or the options changed. The objects are compared with what they were only where
    // scene::Scene::revision changed since the last call; under an unchanged revision only kSpotChecks objects are
    // (the next ones in turn), so a frame where nothing moved costs nothing per object. The renderer calls it once per
    // frame before planning; the constructor once with default options. Throws rhi::Error where objects were added or
    // removed since the upload, and where a spot check finds an object changed under an unchanged revision (an edit
    // its editor did not report).
    void refresh(const CasterOptions& options) const;
    // Objects compared per refresh() under an unchanged scene::Scene::revision: an unreported edit is found within
    // objects / kSpotChecks frames, in the first frame in a scene of fewer objects.
    static constexpr std::size_t kSpotChecks = 1024;
    // Objects whose material casts shadows, with their world bounds, as of the last refresh().
    const std::vector<shadows::ShadowCaster>& casters() const { return casters_; }
    // What a deformed object's vertices are posed by this frame (a hash of its joint matrices and morph weights in
    // scene::Rig::pose), 0 for an object drawn as uploaded: ShadowCaster::pose, which caches compare.
    std::uint64_t poseKey(std::size_t object) const;
    // Every shadow caster's world bounds, in caster order, as of the last refresh().
    const std::vector<shadows::Bounds>& casterBounds() const { return casterBounds_; }
    // Indices into casters() of the casters whose objects are static (scene::Mobility), ascending.
    const std::vector<std::uint32_t>& staticCasters() const { return staticCasters_; }
    // Which casters each refresh() changed: what keeps casters resident rewrites only those.
    const shadows::CasterChanges& casterChanges() const { return casterChanges_; }
    // Which objects each refresh() found moved (indices into Scene::objects; all where the lists were built anew, as
    // after a change of an object's shadow casting or receiving or of a material): what keeps the lit instances
    // resident (GpuViewCulling) rewrites only those.
    const shadows::CasterChanges& objectChanges() const { return objectChanges_; }

    // The vertex layout the caster passes read from the scene's vertex buffers.
    static shadows::CasterVertexFormat vertexFormat();
    // scene::Vertex's six attributes at locations 0 to 5 (position, normal, uv, uv1, tangent, colour), as the
    // lit shaders read them, and the instance transforms (shadows::addInstanceAttributes) from vertex buffer slot
    // shadows::kInstanceSlot; a pass whose shader reads fewer removes the others.
    static rhi::VertexLayout vertexLayout();

    // Objects of one lit draw group share mesh, material and whether they receive shadows: instances of one draw in
    // the lit pass and the depth prepass. Casters' draw groups (ShadowCaster::drawGroup) are made alike.
    std::uint32_t litDrawGroup(std::uint32_t object) const;

    // Binds the material's maps (material textures, or the white texel) at firstMapBinding + scene::TextureSlot and
    // the base colour map with coverageSampler() at coverageBinding, then the object's mesh and `instances`
    // (shadows::InstanceTransform each).
    void bindWithMaps(rhi::CommandList& commands, const scene::Object& object, std::uint32_t firstMapBinding,
                      std::uint32_t coverageBinding, const rhi::BufferSlice& instances) const;
    // bindWithMaps, then draws instanceCount instances of the mesh.
    void drawWithMaps(rhi::CommandList& commands, const scene::Object& object, std::uint32_t firstMapBinding,
                      std::uint32_t coverageBinding, const rhi::BufferSlice& instances,
                      std::uint32_t instanceCount) const;
    // The uv transform rows of a material texture (identity on TEXCOORD_0 without one).
    static shadows::UvTransformRows uvTransform(const std::optional<scene::MaterialTexture>& texture);

private:
    // A caster of the material, without mesh, transform and draw group.
    shadows::ShadowCaster materialCaster(const scene::Material& material) const;

    struct Mesh {
        std::unique_ptr<rhi::Buffer> vertices;
        std::unique_ptr<rhi::Buffer> indices;
    };
    const scene::Scene& scene_;
    std::vector<Mesh> meshes_;
    // Per object: the objects of one mesh and material share a number (an object's mesh and material never change).
    std::vector<std::uint32_t> meshMaterialGroups_;
    // Per object: its scene::Rig::deformers index, -1 for an object not deformed.
    std::vector<std::int32_t> deformers_;
    // What an object was at the last refresh(), as far as its caster depends on it.
    struct ObjectSnapshot {
        glm::mat4 transform{1.0f};
        scene::Bounds worldBounds;
        scene::ShadowCasting castShadows = scene::ShadowCasting::On;
        bool receiveShadows = true;
        scene::Mobility mobility = scene::Mobility::Static;
    };
    // What the lists depend on of a material besides its caster: whether its objects are lit opaque or blended, and
    // receive shadows (their lit draw group).
    struct MaterialKey {
        scene::CasterMode caster = scene::CasterMode::On;
        bool blend = false;
        bool receiveShadows = true;
        bool operator==(const MaterialKey&) const = default;
    };
    static constexpr std::uint32_t kNoCaster = 0xffffffffu;
    // Builds the caster list, bounds and static casters anew.
    void rebuildCasters(const CasterOptions& options) const;
    // Whether the materials' casters differ from those the list was built with (and keeps the new ones).
    bool materialsChanged() const;
    // Compares objects [first, end) with their snapshots: rewrites the casters of moved ones and logs them. Returns
    // whether the lists must be built anew. `reported`: the scene's revision changed; otherwise a change throws.
    bool compareObjects(std::size_t first, std::size_t end, bool reported) const;

    // refresh()'s caches: the renderer plans from a const scene, as the shadow caches do.
    mutable std::vector<shadows::ShadowCaster> casters_;
    mutable std::vector<shadows::Bounds> casterBounds_;
    mutable std::vector<std::uint32_t> staticCasters_;
    mutable std::vector<ObjectSnapshot> snapshots_; // per object
    mutable std::vector<std::uint32_t> casterOf_; // per object: its index in casters_, or kNoCaster
    mutable std::vector<shadows::ShadowCaster> materialCasters_; // per material, as materialCaster() made it
    mutable std::vector<MaterialKey> materialKeys_; // per material
    mutable std::optional<CasterOptions> options_; // those of the last refresh
    mutable shadows::CasterChanges casterChanges_;
    mutable shadows::CasterChanges objectChanges_;
    mutable std::optional<std::uint64_t> revision_; // the scene's at the last refresh
    mutable std::size_t spotCheck_ = 0; // the first object the next spot checks compare
    std::vector<std::uint32_t> deformedObjects_; // ascending
    rhi::Device& device_;
    std::vector<std::unique_ptr<rhi::Texture>> textures_;
    std::vector<std::unique_ptr<rhi::Sampler>> samplers_; // one per texture
    std::vector<std::unique_ptr<rhi::Sampler>> coverageSamplers_; // one per texture, without anisotropy
    float anisotropy_ = 1.0f;
    std::unique_ptr<rhi::Texture> white_;
    std::unique_ptr<rhi::Sampler> whiteSampler_;
};

} // namespace penumbra::render
