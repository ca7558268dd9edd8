#include "penumbra/scene/Scene.hpp"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace penumbra::scene {
namespace {

constexpr std::array<std::pair<ShadowCasting, std::string_view>, 4> kShadowCastingNames{{
    {ShadowCasting::On, "on"},
    {ShadowCasting::Off, "off"},
    {ShadowCasting::TwoSided, "twoSided"},
    {ShadowCasting::ShadowsOnly, "shadowsOnly"},
}};

constexpr std::array<std::pair<Mobility, std::string_view>, 2> kMobilityNames{{
    {Mobility::Static, "static"},
    {Mobility::Dynamic, "dynamic"},
}};

template <typename Enum, std::size_t N>
std::string_view nameIn(const std::array<std::pair<Enum, std::string_view>, N>& names, Enum value)
{
    for (const auto& [known, name] : names)
        if (known == value)
            return name;
    return "unknown";
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueIn(const std::array<std::pair<Enum, std::string_view>, N>& names, std::string_view name)
{
    for (const auto& [value, known] : names)
        if (known == name)
            return value;
    return std::nullopt;
}

constexpr float kUnitTolerance = 1e-3f;
// Relative to the box's extent: the stored box may come from another float evaluation order.
constexpr float kBoundsTolerance = 1e-4f;

std::string describe(const char* kind, std::size_t index, const std::string& name)
{
    return name.empty() ? fmt::format("{} {}", kind, index) : fmt::format("{} {} ('{}')", kind, index, name);
}

bool isUnit(const glm::vec3& v) { return std::abs(glm::length(v) - 1.0f) <= kUnitTolerance; }

bool sameBounds(const Bounds& a, const Bounds& b)
{
    const float tolerance = kBoundsTolerance * (1.0f + glm::length(b.size()) + glm::length(b.center()));
    return glm::all(glm::lessThanEqual(glm::abs(a.min - b.min), glm::vec3(tolerance))) &&
           glm::all(glm::lessThanEqual(glm::abs(a.max - b.max), glm::vec3(tolerance)));
}

void validateMesh(const MeshData& mesh, std::size_t index)
{
    if (mesh.indices.size() % 3 != 0)
        throw SceneError(
            fmt::format("mesh {}: {} indices is not a whole number of triangles", index, mesh.indices.size()));
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        if (mesh.indices[i] >= mesh.vertices.size())
            throw SceneError(fmt::format("mesh {}: index {} refers to vertex {}, but the mesh has {} vertices", index,
                                         i, mesh.indices[i], mesh.vertices.size()));
    }
}

void validateObject(const Scene& scene, const Object& object, std::size_t index)
{
    const std::string what = describe("object", index, object.name);
    if (object.mesh >= scene.meshes.size())
        throw SceneError(fmt::format("{}: mesh {} does not exist (the scene has {} meshes)", what, object.mesh,
                                     scene.meshes.size()));
    if (object.material >= scene.materials.size())
        throw SceneError(fmt::format("{}: material {} does not exist (the scene has {} materials)", what,
                                     object.material, scene.materials.size()));
    // The renderer keeps an instance's first three rows only (shadows::InstanceTransform).
    const glm::vec4 lastRow(object.transform[0][3], object.transform[1][3], object.transform[2][3],
                            object.transform[3][3]);
    if (lastRow != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f))
        throw SceneError(fmt::format("{}: the transform's last row is ({}, {}, {}, {}); object transforms are affine, "
                                     "their last row (0, 0, 0, 1)",
                                     what, lastRow.x, lastRow.y, lastRow.z, lastRow.w));
    if (!sameBounds(object.worldBounds, scene.meshes[object.mesh].bounds.transformed(object.transform)))
        throw SceneError(fmt::format("{}: worldBounds do not match mesh {} under the object's transform (stale bounds)",
                                     what, object.mesh));
}

void validateMaterial(const Scene& scene, const Material& material, std::size_t index)
{
    const std::string what = describe("material", index, material.name);
    for (std::size_t slot = 0; slot < kTextureSlots; ++slot) {
        const std::optional<MaterialTexture>& texture = material.textures[slot];
        if (!texture)
            continue;
        if (texture->image >= scene.textures.size())
            throw SceneError(fmt::format("{}: texture {} does not exist (the scene has {} textures)", what,
                                         texture->image, scene.textures.size()));
        if (texture->texCoord >= kTexCoordSets)
            throw SceneError(fmt::format("{}: texture slot {} reads uv set {}, allowed 0 to {}", what, slot,
                                         texture->texCoord, kTexCoordSets - 1));
    }
    if (material.occlusionStrength < 0.0f || material.occlusionStrength > 1.0f)
        throw SceneError(fmt::format("{}: occlusionStrength {} is outside [0, 1]", what, material.occlusionStrength));
    if (!(glm::all(glm::greaterThanEqual(material.emissive, glm::vec3(0.0f))) &&
          glm::all(glm::lessThan(material.emissive, glm::vec3(std::numeric_limits<float>::infinity())))))
        throw SceneError(fmt::format("{}: emissive ({}, {}, {}) is not finite and at least 0", what,
                                     material.emissive.x, material.emissive.y, material.emissive.z));
}

void validateTexture(const TextureImage& texture, std::size_t index)
{
    const std::size_t expected = std::size_t(texture.width) * texture.height * 4;
    if (texture.width == 0 || texture.height == 0 || texture.rgba.size() != expected)
        throw SceneError(fmt::format("{}: {}x{} texels need {} RGBA8 bytes, it has {}",
                                     describe("texture", index, texture.name), texture.width, texture.height, expected,
                                     texture.rgba.size()));
}

void validateLight(const DirectionalLight& light, std::size_t index)
{
    const std::string what = describe("light", index, light.name);
    if (!isUnit(light.direction))
        throw SceneError(fmt::format("{}: direction ({}, {}, {}) is not a unit vector", what, light.direction.x,
                                     light.direction.y, light.direction.z));
    if (light.shadowStrength < 0.0f || light.shadowStrength > 1.0f)
        throw SceneError(fmt::format("{}: shadowStrength {} is outside [0, 1]", what, light.shadowStrength));
    if (!(light.angularDiameter >= 0.0f && light.angularDiameter <= kMaxAngularDiameter))
        throw SceneError(fmt::format("{}: angularDiameter {} is outside [0, {}] degrees", what, light.angularDiameter,
                                     kMaxAngularDiameter));
}

void validateSourceRadius(const std::string& what, float radius, float range)
{
    if (!(radius >= 0.0f && radius <= range))
        throw SceneError(fmt::format("{}: sourceRadius {} is outside [0, range {}]", what, radius, range));
}

void validateShadowResolution(const std::string& what, const std::optional<float>& resolution)
{
    if (resolution && !(*resolution >= kMinShadowResolution && *resolution <= kMaxShadowResolution))
        throw SceneError(fmt::format("{}: shadowResolution {} is outside [{}, {}] texels", what, *resolution,
                                     kMinShadowResolution, kMaxShadowResolution));
}

void validateLocalLight(const std::string& what, float range, float strength, float shadowNearPlane)
{
    if (!(range > 0.0f && std::isfinite(range)))
        throw SceneError(fmt::format("{}: range {} must be positive and finite", what, range));
    if (!(shadowNearPlane >= 0.0f && shadowNearPlane < range))
        throw SceneError(fmt::format("{}: shadowNearPlane {} must be in [0, range {}) (0: the shadow settings' "
                                     "local.nearPlane)",
                                     what, shadowNearPlane, range));
    if (strength < 0.0f || strength > 1.0f)
        throw SceneError(fmt::format("{}: shadowStrength {} is outside [0, 1]", what, strength));
}

void validateSpotLight(const SpotLight& light, std::size_t index)
{
    const std::string what = describe("spot light", index, light.name);
    if (!isUnit(light.direction))
        throw SceneError(fmt::format("{}: direction ({}, {}, {}) is not a unit vector", what, light.direction.x,
                                     light.direction.y, light.direction.z));
    if (!(light.innerAngle >= 0.0f && light.innerAngle < light.outerAngle && light.outerAngle < 1.5707963f))
        throw SceneError(fmt::format("{}: angles inner {} outer {} need 0 <= inner < outer < pi/2 radians", what,
                                     light.innerAngle, light.outerAngle));
    validateLocalLight(what, light.range, light.shadowStrength, light.shadowNearPlane);
    validateSourceRadius(what, light.sourceRadius, light.range);
    validateShadowResolution(what, light.shadowResolution);
}

void validatePointLight(const PointLight& light, std::size_t index)
{
    const std::string what = describe("point light", index, light.name);
    validateLocalLight(what, light.range, light.shadowStrength, light.shadowNearPlane);
    validateSourceRadius(what, light.sourceRadius, light.range);
    validateShadowResolution(what, light.shadowResolution);
}

void validateCamera(const Camera& camera)
{
    if (!isUnit(camera.forward))
        throw SceneError("camera: forward is not a unit vector");
    if (glm::length(glm::cross(camera.forward, camera.up)) < kUnitTolerance)
        throw SceneError("camera: up is parallel to forward");
    if (!(camera.nearPlane > 0.0f && camera.farPlane > camera.nearPlane))
        throw SceneError(
            fmt::format("camera: planes near {} far {} need 0 < near < far", camera.nearPlane, camera.farPlane));
    if (!(camera.fovY > 0.0f && camera.fovY < 3.14159f))
        throw SceneError(fmt::format("camera: fovY {} radians is outside (0, pi)", camera.fovY));
}

} // namespace

std::string_view shadowCastingName(ShadowCasting casting) { return nameIn(kShadowCastingNames, casting); }

std::optional<ShadowCasting> parseShadowCasting(std::string_view name) { return valueIn(kShadowCastingNames, name); }

std::string_view mobilityName(Mobility mobility) { return nameIn(kMobilityNames, mobility); }

std::optional<Mobility> parseMobility(std::string_view name) { return valueIn(kMobilityNames, name); }

std::uint32_t Scene::addMesh(MeshData mesh)
{
    meshes.push_back(std::move(mesh));
    return static_cast<std::uint32_t>(meshes.size() - 1);
}

std::uint32_t Scene::addMaterial(Material material)
{
    materials.push_back(std::move(material));
    return static_cast<std::uint32_t>(materials.size() - 1);
}

std::uint32_t Scene::addObject(std::string name, std::uint32_t mesh, std::uint32_t material, const glm::mat4& transform)
{
    if (mesh >= meshes.size())
        throw SceneError(
            fmt::format("addObject '{}': mesh {} does not exist (the scene has {} meshes)", name, mesh, meshes.size()));
    const Bounds bounds = meshes[mesh].bounds.transformed(transform);
    objects.push_back({std::move(name), mesh, material, transform, bounds});
    return static_cast<std::uint32_t>(objects.size() - 1);
}

std::optional<std::uint32_t> Scene::findObject(std::string_view name) const
{
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (objects[i].name == name)
            return static_cast<std::uint32_t>(i);
    }
    return std::nullopt;
}

Bounds Scene::worldBounds() const
{
    Bounds result;
    for (const Object& object : objects)
        result.extend(object.worldBounds);
    return result;
}

void Scene::validate() const
{
    for (std::size_t i = 0; i < meshes.size(); ++i)
        validateMesh(meshes[i], i);
    for (std::size_t i = 0; i < textures.size(); ++i)
        validateTexture(textures[i], i);
    for (std::size_t i = 0; i < materials.size(); ++i)
        validateMaterial(*this, materials[i], i);
    for (std::size_t i = 0; i < objects.size(); ++i)
        validateObject(*this, objects[i], i);
    for (std::size_t i = 0; i < lights.size(); ++i)
        validateLight(lights[i], i);
    for (std::size_t i = 0; i < spotLights.size(); ++i)
        validateSpotLight(spotLights[i], i);
    for (std::size_t i = 0; i < pointLights.size(); ++i)
        validatePointLight(pointLights[i], i);
    validateCamera(camera);
}

} // namespace penumbra::scene
