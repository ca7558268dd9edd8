#pragma once

#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/Geometry.hpp"
#include "penumbra/scene/Light.hpp"
#include "penumbra/scene/Material.hpp"
#include "penumbra/scene/Rig.hpp"
#include "penumbra/scene/TextureImage.hpp"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::scene {

// A scene that refers to something it does not hold (a mesh or material index out of range,
// an index past a mesh's vertices) or holds a value no pass can use. what() names the
// object, mesh or light by index (and name) and the bad reference.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Whether an object casts shadows, and how, on top of what its material says (Material::caster decides
// which texels of a casting surface block light). The per-renderer choice of Unity's
// Rendering.ShadowCastingMode (Scripting API), which real-time scenes rely on for proxies and for
// hiding shadow-only geometry.
enum class ShadowCasting : std::uint8_t {
    On, // casts as its material says, culled as the material says (doubleSided casts both faces)
    Off, // drawn, casts nothing
    TwoSided, // casts with both faces whatever its material's culling
    ShadowsOnly, // not drawn, casts as On
};

// "on", "off", "twoSided", "shadowsOnly": the names in glTF extras and in the viewer.
std::string_view shadowCastingName(ShadowCasting casting);
std::optional<ShadowCasting> parseShadowCasting(std::string_view name);

// Whether an object may move: static casters' shadows can be kept between frames or baked (Unity's
// "Static" flag and HDRP's cached shadow maps, Godot's static/dynamic split); dynamic ones are drawn every frame.
enum class Mobility : std::uint8_t { Static, Dynamic };

std::string_view mobilityName(Mobility mobility);
std::optional<Mobility> parseMobility(std::string_view name);

// One drawn instance: meshes[mesh] with materials[material], placed by transform.
// worldBounds = meshes[mesh].bounds.transformed(transform); Scene::addObject fills it and
// validate() rejects a stale one, because shadow fitting and culling trust it.
// The transform may be any invertible affine map (validate() rejects a last row other than
// (0, 0, 0, 1)): normals go through its inverse transpose (the lit pass, the ground truth). A mirroring transform
// (negative determinant) turns counter-clockwise triangles clockwise, so such an object needs a mesh with reversed
// winding (the glTF loader makes one) to keep its outside front-facing.
struct Object {
    std::string name;
    std::uint32_t mesh = 0;
    std::uint32_t material = 0;
    glm::mat4 transform{1.0f};
    Bounds worldBounds;
    ShadowCasting castShadows = ShadowCasting::On;
    // False: lit as if nothing blocked its lights (and its material's receiveShadows = false does the same).
    bool receiveShadows = true;
    Mobility mobility = Mobility::Static;
};

// Everything a frame draws: meshes, materials, textures, objects, lights and a camera.
struct Scene {
    std::vector<MeshData> meshes;
    std::vector<Material> materials;
    std::vector<Object> objects;
    std::vector<DirectionalLight> lights;
    std::vector<SpotLight> spotLights;
    std::vector<PointLight> pointLights;
    std::vector<TextureImage> textures; // referred to by Material::textures
    Camera camera;
    // A glTF file's nodes, skins, morph targets and animations, to pose the objects at another time (Posing.hpp).
    Rig rig;
    // Raised by whoever edits objects in place (transform and worldBounds, castShadows, receiveShadows, mobility) once
    // a renderer draws the scene: the renderer reads the objects again only where it changed, so a frame where nothing
    // moved costs nothing per object. poseScene raises it; an edit left unreported is caught (render::GpuScene::refresh
    // throws where its spot checks find an object changed under an unchanged revision).
    std::uint64_t revision = 0;

    // Adds a mesh and returns its index.
    std::uint32_t addMesh(MeshData mesh);
    // Adds a material and returns its index.
    std::uint32_t addMaterial(Material material);
    // Appends an object with its world bounds computed; the mesh must already be added.
    std::uint32_t addObject(std::string name, std::uint32_t mesh, std::uint32_t material, const glm::mat4& transform);

    // Index of the first object called `name`.
    std::optional<std::uint32_t> findObject(std::string_view name) const;
    // The material an object is drawn with.
    const Material& materialOf(const Object& object) const { return materials.at(object.material); }
    // The mesh an object draws.
    const MeshData& meshOf(const Object& object) const { return meshes.at(object.mesh); }
    // Shadow maps darken the object: both it and its material receive shadows.
    bool receivesShadows(const Object& object) const
    {
        return object.receiveShadows && materialOf(object).receiveShadows;
    }
    // The object enters shadow maps: neither it nor its material is set not to cast.
    bool castsShadows(const Object& object) const
    {
        return object.castShadows != ShadowCasting::Off && materialOf(object).caster != CasterMode::Off;
    }

    // Box of every object's world bounds (empty for a scene without objects).
    Bounds worldBounds() const;

    // Throws SceneError for the first broken reference or unusable value found.
    void validate() const;
};

} // namespace penumbra::scene
