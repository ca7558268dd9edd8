#include "penumbra/gltf/GltfLoader.hpp"

#include "GltfDocument.hpp"
#include "GltfFile.hpp"
#include "GltfNodes.hpp"
#include "GltfRig.hpp"
#include "GltfUnsupported.hpp"

#include "penumbra/scene/SceneDefaults.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra::gltf {
namespace {

// glTF allows an outer cone angle of exactly pi/2; a spot shadow's perspective projection does not.
constexpr float kMaxSpotOuterAngle = 1.5707963f - 1e-3f;
// Behind the farthest corner of the scene, so an infinite glTF far plane clips nothing.
constexpr float kFarPlaneMargin = 1.05f;

glm::vec3 origin(const glm::mat4& world) { return glm::vec3(world[3]); }

// glTF lights and cameras look down their node's -z.
glm::vec3 forward(const glm::mat4& world) { return glm::normalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f)); }

float defaultRange(float intensity) { return std::max(kDefaultRangePerSqrtIntensity * std::sqrt(intensity), 1.0f); }

// The light's source size from its `extras` {"sourceSize": S} (degrees of angular diameter for directional lights,
// world units of radius for spot and point lights), or `fallback` without one.
float sourceSize(const Document& document, const tinygltf::Light& light, const std::string& owner, float fallback)
{
    if (!light.extras.IsObject() || !light.extras.Has("sourceSize"))
        return fallback;
    const tinygltf::Value& value = light.extras.Get("sourceSize");
    if (!value.IsNumber() && !value.IsInt())
        document.fail(fmt::format("{}: extras.sourceSize is not a number", owner));
    return float(value.GetNumberAsDouble());
}

// The light's static shadow map mode from its `extras` {"shadowUpdate": "onDemand"} (scene::parseLightShadowUpdate's
// names), the shadow settings' without one.
scene::LightShadowUpdate shadowUpdate(const Document& document, const tinygltf::Light& light, const std::string& owner)
{
    if (!light.extras.IsObject() || !light.extras.Has("shadowUpdate"))
        return std::nullopt;
    const tinygltf::Value& value = light.extras.Get("shadowUpdate");
    const std::optional<scene::LightShadowUpdate> update =
        value.IsString() ? scene::parseLightShadowUpdate(value.Get<std::string>()) : std::nullopt;
    if (!update)
        document.fail(fmt::format("{}: extras.shadowUpdate is not one of {}", owner, scene::kLightShadowUpdateNames));
    return *update;
}

// A spot or point light's own shadow tile resolution from its `extras` {"shadowResolution": N} (texels per side),
// nullopt (the shadow settings' local.tileResolution) without one.
std::optional<float> shadowResolution(const Document& document, const tinygltf::Light& light, const std::string& owner)
{
    if (!light.extras.IsObject() || !light.extras.Has("shadowResolution"))
        return std::nullopt;
    const tinygltf::Value& value = light.extras.Get("shadowResolution");
    if (!value.IsNumber() && !value.IsInt())
        document.fail(fmt::format("{}: extras.shadowResolution is not a number", owner));
    return float(value.GetNumberAsDouble());
}

void addLight(const Document& document, const LightInstance& instance, scene::Scene& world,
              std::vector<std::string>& notes)
{
    const tinygltf::Light& light = document.model().lights[std::size_t(instance.light)];
    const std::string owner = describe("light", instance.light, light.name);
    glm::vec3 color(1.0f);
    if (light.color.size() == 3)
        color = glm::vec3(float(light.color[0]), float(light.color[1]), float(light.color[2]));
    else if (!light.color.empty())
        document.fail(fmt::format("{}: color has {} values, expected 3", owner, light.color.size()));
    const auto intensity = float(light.intensity);
    const float range = light.range > 0.0 ? float(light.range) : defaultRange(intensity);
    if (light.type == "directional") {
        world.lights.push_back(
            {.name = light.name,
             .color = color,
             .intensity = intensity,
             .direction = forward(instance.world),
             .angularDiameter = sourceSize(document, light, owner, scene::LightShadowDefaults::angularDiameter),
             .shadowUpdate = shadowUpdate(document, light, owner)});
    } else if (light.type == "spot") {
        auto outer = float(light.spot.outerConeAngle);
        if (outer > kMaxSpotOuterAngle) {
            notes.push_back(
                fmt::format("{}: outer cone angle {} narrowed to {} radians", owner, outer, kMaxSpotOuterAngle));
            outer = kMaxSpotOuterAngle;
        }
        world.spotLights.push_back(
            {.name = light.name,
             .color = color,
             .intensity = intensity,
             .position = origin(instance.world),
             .direction = forward(instance.world),
             .range = range,
             .innerAngle = float(light.spot.innerConeAngle),
             .outerAngle = outer,
             .sourceRadius = sourceSize(document, light, owner, scene::LightShadowDefaults::sourceRadius),
             .shadowUpdate = shadowUpdate(document, light, owner),
             .shadowResolution = shadowResolution(document, light, owner)});
    } else if (light.type == "point") {
        world.pointLights.push_back(
            {.name = light.name,
             .color = color,
             .intensity = intensity,
             .position = origin(instance.world),
             .range = range,
             .sourceRadius = sourceSize(document, light, owner, scene::LightShadowDefaults::sourceRadius),
             .shadowUpdate = shadowUpdate(document, light, owner),
             .shadowResolution = shadowResolution(document, light, owner)});
    } else {
        document.fail(fmt::format("{}: type '{}' is not directional, spot or point", owner, light.type));
    }
}

bool isNamed(const Document& document, const CameraInstance& instance, const std::string& name)
{
    return document.model().cameras[std::size_t(instance.camera)].name == name ||
           document.model().nodes[std::size_t(instance.node)].name == name;
}

std::string cameraNames(const Document& document, const std::vector<CameraInstance>& cameras)
{
    std::string names;
    for (const CameraInstance& instance : cameras) {
        const std::string& name = document.model().cameras[std::size_t(instance.camera)].name;
        names += fmt::format("{}'{}'", names.empty() ? "" : ", ",
                             name.empty() ? document.model().nodes[std::size_t(instance.node)].name : name);
    }
    return names.empty() ? "none" : names;
}

scene::Camera toCamera(const Document& document, const CameraInstance& instance, const scene::Bounds& bounds)
{
    const tinygltf::Camera& gltfCamera = document.model().cameras[std::size_t(instance.camera)];
    const std::string owner = describe("camera", instance.camera, gltfCamera.name);
    if (gltfCamera.type != "perspective")
        document.fail(fmt::format("{}: type '{}' is not supported, only perspective", owner, gltfCamera.type));
    const glm::mat3 rotation(instance.world);
    scene::Camera camera{.position = origin(instance.world),
                         .forward = forward(instance.world),
                         .up = glm::normalize(rotation * glm::vec3(0.0f, 1.0f, 0.0f)),
                         .fovY = float(gltfCamera.perspective.yfov),
                         .nearPlane = float(gltfCamera.perspective.znear)};
    if (gltfCamera.perspective.zfar > 0.0) {
        camera.farPlane = float(gltfCamera.perspective.zfar);
    } else {
        float farthest = 0.0f;
        if (!bounds.empty())
            for (const glm::vec3& corner : bounds.corners())
                farthest = std::max(farthest, glm::length(corner - camera.position));
        camera.farPlane = std::max(kFarPlaneMargin * farthest, 1000.0f * camera.nearPlane);
    }
    return camera;
}

scene::Camera chooseCamera(const Document& document, const std::vector<CameraInstance>& cameras,
                           const GltfOptions& options, const scene::Bounds& bounds, std::vector<std::string>& notes)
{
    if (options.camera) {
        for (const CameraInstance& instance : cameras)
            if (isNamed(document, instance, *options.camera))
                return toCamera(document, instance, bounds);
        document.fail(fmt::format("no camera named '{}'; the scene's cameras: {}", *options.camera,
                                  cameraNames(document, cameras)));
    }
    for (const CameraInstance& instance : cameras)
        if (document.model().cameras[std::size_t(instance.camera)].type == "perspective")
            return toCamera(document, instance, bounds);
    notes.push_back(cameras.empty() ? "no camera: framing the scene's bounds"
                                    : "no perspective camera: framing the scene's bounds");
    return scene::framingCamera(bounds, scene::Camera{}.fovY, options.aspect);
}

} // namespace

namespace {

GltfScene toScene(const Document& document, std::vector<std::string> readNotes, const GltfOptions& options)
{
    GltfScene result;
    result.notes = std::move(readNotes);
    scene::Scene& world = result.scene;
    std::vector<std::string>& notes = result.notes;
    checkSupport(document, notes);
    const NodeWalk walk = walkNodes(document, world, notes);
    readRig(document, walk, world, notes);
    for (const LightInstance& light : walk.lights)
        addLight(document, light, world, notes);
    world.camera = chooseCamera(document, walk.cameras, options, world.worldBounds(), notes);
    if (world.lights.empty() && world.spotLights.empty() && world.pointLights.empty()) {
        world.lights.push_back(scene::defaultSun(world.camera));
        result.defaultLights = true;
        notes.push_back(
            fmt::format("no lights: added a default sun with shadows, {:g} degrees up over the camera's left "
                        "shoulder",
                        scene::kDefaultSunElevationDegrees));
    }
    for (std::string& note : document.deviations().notes())
        notes.push_back(std::move(note));
    try {
        world.validate();
    } catch (const GltfError&) {
        throw;
    } catch (const scene::SceneError& error) {
        document.fail(error.what());
    }
    return result;
}

} // namespace

GltfScene loadGltf(const std::filesystem::path& path, const GltfOptions& options)
{
    std::vector<std::string> notes;
    const Document document = readDocument(path, notes, options.missingTextures, options.imageProgress);
    return toScene(document, std::move(notes), options);
}

GltfScene loadGltf(std::span<const std::uint8_t> bytes, const std::string& name, const std::filesystem::path& folder,
                   const GltfOptions& options)
{
    std::vector<std::string> notes;
    const Document document = readDocument(name, bytes, folder, notes, options.missingTextures, options.imageProgress);
    return toScene(document, std::move(notes), options);
}

} // namespace penumbra::gltf
